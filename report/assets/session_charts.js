// Session charts: severity against clearance and against crank speed.
  // Session: severity against clearance (one line per speed) and against speed (one per clearance).
  function severity(id, groups, xkey, xlabel, ykeys, ylabels, yunit, groupLabel, y2){
    if (!document.getElementById(id)) return;
    var xs = [];
    groups.forEach(function(g){ g.points.forEach(function(p){ if (xs.indexOf(p[xkey]) < 0) xs.push(p[xkey]); }); });
    xs.sort(function(a, b){ return a - b; });
    var labels = [xlabel], series = {};
    groups.forEach(function(g){ ykeys.forEach(function(k, j){ var l = ylabels[j] + ' @ ' + groupLabel(g.value); labels.push(l);
      if (y2 && j === ykeys.length - 1) series[l] = {axis: 'y2'}; }); });
    var data = xs.map(function(xv){ var row = [xv];
      groups.forEach(function(g){ ykeys.forEach(function(k){ var p = g.points.filter(function(p){ return p[xkey] === xv; })[0];
        row.push(p && p[k] !== null ? p[k] : null); }); }); return row; });
    var opts = {drawPoints: true, pointSize: 4, strokeWidth: 1.5, xlabel: xlabel, ylabel: yunit, series: series};
    if (y2) opts.y2label = y2;
    chart(id, data, labels, opts);
  }
  var S = R.severity;
  var rpm = function(v){ return v.toFixed(0) + ' rpm'; }, mm = function(v){ return v.toFixed(4) + ' mm'; };
  severity('sev-clearance', S.by_speed, 'clearance_mm', 'radial clearance (mm)', ['measured_alpha3_fluctuation_rms', 'simulated_alpha3_fluctuation_rms'],
           ['measured', 'clearance model'], 'RMS of α3 − nominal (rad/s²)', rpm);
  severity('sev-clearance-sim', S.by_speed, 'clearance_mm', 'radial clearance (mm)', ['sum_normal_impulse_per_rev_Ns', 'impacts_per_rev'],
           ['ΣF per turn', 'n per turn'], 'ΣF per turn (N·s)', rpm, 'impacts per turn n');
  severity('sev-speed', S.by_clearance, 'speed_rpm', 'crank speed (rpm)', ['measured_alpha3_fluctuation_rms', 'simulated_alpha3_fluctuation_rms'],
           ['measured', 'clearance model'], 'RMS of α3 − nominal (rad/s²)', mm);
  severity('sev-speed-sim', S.by_clearance, 'speed_rpm', 'crank speed (rpm)', ['sum_normal_impulse_per_rev_Ns', 'impacts_per_rev'],
           ['ΣF per turn', 'n per turn'], 'ΣF per turn (N·s)', mm, 'impacts per turn n');
