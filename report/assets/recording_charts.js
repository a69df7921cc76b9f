// Per recording: overlays of measured, clearance model and nominal; deviation
// per crank order and the magnification factor; the measured spectrum.
  var colors = {measured:'#1f5fbf', clearance:'#c0392b', nominal:'#2e7d32', modified:'#8e44ad'};
  var names = {alpha3_rad_s2:['α3','rad/s²'], omega3_rad_s:['ω3','rad/s'], alpha4_rad_s2:['α4','rad/s²'], omega4_rad_s:['ω4','rad/s']};

  R.recordings.forEach(function(rec, ri){
    if (rec.status !== 'ok' && rec.status !== 'check set-up') return;
    var x = rec.grid.crank_deg;
    Object.keys(rec.series).forEach(function(q){
      var s = rec.series[q], id = 'r' + ri + '-' + q; if (!document.getElementById(id)) return;
      var labels = ['crank angle (deg)'], cols = [], col = [];
      function band(m, sd){ return function(i){ var d = sd ? sd[i] : 0; return [m[i]-d, m[i], m[i]+d]; }; }
      if (s.measured){ labels.push('measured (mean ± std)'); cols.push(band(s.measured, s.measured_std)); col.push(colors.measured); }
      labels.push('clearance model (mean ± std)'); cols.push(band(s.clearance, s.clearance_std)); col.push(colors.clearance);
      labels.push('nominal'); cols.push(band(s.nominal)); col.push(colors.nominal);
      if (s.modified && s.modified.length){ labels.push('modified analytical (÷ a)'); cols.push(band(s.modified)); col.push(colors.modified); }
      var data = x.map(function(xv, i){ return [xv].concat(cols.map(function(f){ return f(i); })); });
      chart(id, data, labels, {customBars: true, colors: col, strokeWidth: 1.2, showRangeSelector: true, rangeSelectorHeight: 28,
        xlabel: 'crank angle θ2 (deg)', ylabel: names[q][0] + ' (' + names[q][1] + ')'});
    });
    // Deviation amplitudes per crank order and the magnification factor per order.
    var m = rec.metrics.alpha3_rad_s2 || rec.metrics.alpha4_rad_s2, mq = rec.metrics.alpha3_rad_s2 ? 'α3' : 'α4';
    if (m && document.getElementById('r' + ri + '-orders')){
      var o = m.magnification.orders, pos = function(v){ return v > 0 ? v : null; };
      chart('r' + ri + '-orders', o.map(function(e){ return [e.order, pos(e.measured_amplitude), pos(e.simulated_amplitude), pos(e.measured_floor)]; }),
        ['order', 'measured − nominal', 'clearance model − nominal', 'measurement floor'],
        {logscale: true, drawPoints: true, pointSize: 2.5, strokeWidth: 1, colors: [colors.measured, colors.clearance, '#9aa7b4'],
         xlabel: 'crank order', ylabel: mq + ' deviation amplitude'});
      var td = m.magnification.time_domain, sp = m.magnification.spectral;
      chart('r' + ri + '-factor', o.map(function(e){ return [e.order, e.significant ? pos(e.factor) : null, td, sp]; }),
        ['order', 'a per significant order', 'a, time domain', 'a, spectral (band)'],
        {logscale: true, drawPoints: true, pointSize: 3, strokeWidth: 1, colors: ['#d35400', '#34495e', '#16a085'],
         xlabel: 'crank order', ylabel: 'magnification a'});
    }
    if (rec.spectra && document.getElementById('r' + ri + '-spectrum')){
      var keys = Object.keys(rec.spectra), ax = rec.spectra[keys[0]].order;
      chart('r' + ri + '-spectrum', ax.map(function(ov, i){ return [ov].concat(keys.map(function(k){ var v = rec.spectra[k].amplitude[i]; return v > 0 ? v : null; })); }),
        ['order'].concat(keys.map(function(k){ return 'measured ' + names[k][0] + ' (before the filter)'; })),
        {logscale: true, strokeWidth: 1, colors: [colors.measured, '#e67e22'], xlabel: 'crank order', ylabel: 'amplitude (rad/s²)'});
    }
  });

