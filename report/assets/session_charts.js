// Session charts: severity against clearance (one line per speed) and against
// crank speed (one line per clearance). Line colour: the role (measured /
// clearance model); line style: the group; point colour: the recording. A
// session with fewer than two clearances (or speeds) has nothing to draw
// against them: a table (or a note) stands in for those charts.
  var S = R.severity, patterns = [null, [7, 3], [2, 3], [7, 3, 2, 3]];
  function severity(id, groups, xkey, xlabel, ykeys, ylabels, ycolors, yunit, groupLabel, y2){
    if (!document.getElementById(id)) return;
    var xs = [];
    groups.forEach(function(g){ g.points.forEach(function(p){ if (xs.indexOf(p[xkey]) < 0) xs.push(p[xkey]); }); });
    xs.sort(function(a, b){ return a - b; });
    var labels = [xlabel], series = {}, colorList = [], recAt = {};
    groups.forEach(function(g, gi){ ykeys.forEach(function(k, j){ var l = ylabels[j] + ' @ ' + groupLabel(g.value); labels.push(l);
      colorList.push(ycolors[j]);
      series[l] = {strokePattern: patterns[gi % patterns.length]};
      if (y2 && j === ykeys.length - 1) series[l].axis = 'y2';
      recAt[l] = xs.map(function(xv){ var p = g.points.filter(function(p){ return p[xkey] === xv; })[0]; return p ? p.recording : null; }); }); });
    var data = xs.map(function(xv){ var row = [xv];
      groups.forEach(function(g){ ykeys.forEach(function(k){ var p = g.points.filter(function(p){ return p[xkey] === xv; })[0];
        row.push(p && p[k] !== null ? p[k] : null); }); }); return row; });
    var opts = {drawPoints: true, pointSize: 4, strokeWidth: 1.5, xRangePad: 12, includeZero: true, xlabel: xlabel, ylabel: yunit, series: series, colors: colorList,
      drawPointCallback: function(g, setName, ctx, cx, cy, color, size, idx){
        var rec = recAt[setName] ? recAt[setName][idx] : null;
        ctx.beginPath(); ctx.fillStyle = rec !== null && rec in recordingIndex ? recordingColor(recordingIndex[rec]) : color;
        ctx.strokeStyle = color; ctx.lineWidth = 1.5; ctx.arc(cx, cy, size, 0, 2 * Math.PI); ctx.fill(); ctx.stroke(); }};
    if (y2) opts.y2label = y2;
    chart(id, data, labels, opts);
  }
  function distinct(key){ var v = [];
    S.by_speed.forEach(function(g){ g.points.forEach(function(p){ if (v.indexOf(p[key]) < 0) v.push(p[key]); }); }); return v; }
  function removeBox(id){ var d = document.getElementById(id); if (d) d.closest('.chart-box').remove(); }
  function note(text){ var p = document.createElement('p'); p.className = 'note single'; p.textContent = text;
    document.getElementById('sev-table').appendChild(p); }
  var rpm = function(v){ return v.toFixed(0) + ' rpm'; }, mm = function(v){ return shortNumber(v) + ' mm'; };
  var clearances = distinct('clearance_mm'), speeds = distinct('speed_rpm');
  var fluct = 'RMS of α3 − nominal (' + name('alpha3_rad_s2').unit + ')', impulse = name('sum_normal_impulse_per_rev_Ns');
  if (document.getElementById('sev-table')){
    if (clearances.length < 2 && speeds.length < 2){
      // One operating point (or none): a table, not dots on empty axes.
      ['sev-clearance', 'sev-clearance-sim', 'sev-speed', 'sev-speed-sim'].forEach(removeBox);
      var grid = document.getElementById('sev-charts'); if (grid) grid.remove();
      note(clearances.length ? 'One operating point in this session: nothing to draw against clearance or crank speed.'
                             : 'No analysed recording in this session.');
      if (clearances.length){
        var box = document.createElement('div'); box.id = 'sev-one-point'; document.getElementById('sev-table').appendChild(box);
        var rows = [];
        S.by_speed.forEach(function(g){ g.points.forEach(function(p){ rows.push([{swatch: recordingIndex[p.recording], text: p.recording},
          p.speed_rpm, p.clearance_mm, p.measured_alpha3_fluctuation_rms, p.simulated_alpha3_fluctuation_rms,
          p.impacts_per_rev, p.sum_normal_impulse_per_rev_Ns, p.impact_index_Ns]); }); });
        tableInstead('sev-one-point', ['recording', name('speed_rpm').label, name('clearance_mm').label,
          name('measured_alpha3_fluctuation_rms').label, name('simulated_alpha3_fluctuation_rms').label,
          name('impacts_per_rev').label, impulse.label, name('impact_index_Ns').label], rows);
      }
    } else if (clearances.length < 2){
      ['sev-clearance', 'sev-clearance-sim'].forEach(removeBox);
      note('One clearance in this session (' + mm(clearances[0]) + '): nothing to draw against clearance; the charts against crank speed show every recording.');
    } else if (speeds.length < 2){
      ['sev-speed', 'sev-speed-sim'].forEach(removeBox);
      note('One crank speed in this session (' + rpm(speeds[0]) + '): nothing to draw against speed; the charts against clearance show every recording.');
    }
  }
  severity('sev-clearance', S.by_speed, 'clearance_mm', name('clearance_mm').label, ['measured_alpha3_fluctuation_rms', 'simulated_alpha3_fluctuation_rms'],
           ['measured', 'clearance model'], [colors.measured, colors.clearance], fluct, rpm);
  severity('sev-clearance-sim', S.by_speed, 'clearance_mm', name('clearance_mm').label, ['sum_normal_impulse_per_rev_Ns', 'impacts_per_rev'],
           ['ΣF per turn', 'n per turn'], [colors.clearance, colors.modified], 'ΣF per turn (' + impulse.unit + ')', rpm, 'impacts per turn n');
  severity('sev-speed', S.by_clearance, 'speed_rpm', name('speed_rpm').label, ['measured_alpha3_fluctuation_rms', 'simulated_alpha3_fluctuation_rms'],
           ['measured', 'clearance model'], [colors.measured, colors.clearance], fluct, mm);
  severity('sev-speed-sim', S.by_clearance, 'speed_rpm', name('speed_rpm').label, ['sum_normal_impulse_per_rev_Ns', 'impacts_per_rev'],
           ['ΣF per turn', 'n per turn'], [colors.clearance, colors.modified], 'ΣF per turn (' + impulse.unit + ')', mm, 'impacts per turn n');
