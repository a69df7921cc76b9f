// Per recording: overlays of measured, clearance model and nominal (ω as the
// deviation from nominal, the absolute values one tick away: the curves of ω
// lie on one another); deviation per crank order and the magnification
// factor; the measured spectrum.
  R.recordings.forEach(function(rec, ri){
    if (rec.status !== 'ok' && rec.status !== 'check set-up') return;
    var x = rec.grid.crank_deg, xlabel = name('crank_deg').label;
    Object.keys(rec.series).forEach(function(q){
      var s = rec.series[q], id = 'r' + ri + '-' + q; if (!document.getElementById(id)) return;
      var n = name(q), deviationFirst = q.indexOf('omega') === 0;
      function build(deviation){
        var ref = deviation ? s.nominal : null, labels = ['crank angle (deg)'], cols = [], col = [];
        function band(m, sd){ return function(i){
          if (m[i] === null || (ref && ref[i] === null)) return null;
          var d = sd && sd[i] !== null ? sd[i] : 0, r = ref ? ref[i] : 0; return [m[i] - d - r, m[i] - r, m[i] + d - r]; }; }
        if (s.measured){ labels.push('measured (mean ± std)'); cols.push(band(s.measured, s.measured_std)); col.push(colors.measured); }
        labels.push('clearance model (mean ± std)'); cols.push(band(s.clearance, s.clearance_std)); col.push(colors.clearance);
        labels.push('nominal'); cols.push(band(s.nominal)); col.push(colors.nominal);
        if (s.modified && s.modified.length){ labels.push('modified analytical (÷ a)'); cols.push(band(s.modified)); col.push(colors.modified); }
        return {labels: labels, colors: col, ylabel: deviation ? n.symbol + ' − nominal (' + n.unit + ')' : n.axis,
          file: x.map(function(xv, i){ return [xv].concat(cols.map(function(f){ return f(i); })); })};
      }
      var b = build(deviationFirst);
      var g = chart(id, b.file, b.labels, {customBars: true, colors: b.colors, strokeWidth: 1.2, showRangeSelector: true,
        rangeSelectorHeight: 28, xlabel: xlabel, ylabel: b.ylabel});
      var box = document.getElementById(id + '-controls');
      if (deviationFirst && box){
        var lab = document.createElement('label'), cb = document.createElement('input');
        cb.type = 'checkbox'; cb.checked = false; cb.className = 'absolute';
        cb.onchange = function(){ var nb = build(!cb.checked); g.updateOptions({file: nb.file, ylabel: nb.ylabel}); };
        lab.appendChild(cb); lab.appendChild(document.createTextNode(' absolute values (unticked: minus the nominal response)'));
        box.appendChild(lab);
      }
    });
    // Deviation amplitudes per crank order and the magnification factor per order.
    var mk = rec.metrics.alpha3_rad_s2 ? 'alpha3_rad_s2' : 'alpha4_rad_s2', m = rec.metrics[mk], mn = name(mk);
    if (m && document.getElementById('r' + ri + '-orders')){
      var o = m.magnification.orders, pos = function(v){ return v > 0 ? v : null; };
      chart('r' + ri + '-orders', o.map(function(e){ return [e.order, pos(e.measured_amplitude), pos(e.simulated_amplitude), pos(e.measured_floor)]; }),
        ['order', 'measured − nominal', 'clearance model − nominal', 'measurement floor'],
        {logscale: true, drawPoints: true, pointSize: 2.5, strokeWidth: 1, colors: [colors.measured, colors.clearance, colors.floor],
         xlabel: 'crank order (per turn)', ylabel: mn.symbol + ' deviation amplitude (' + mn.unit + ')'});
      var td = m.magnification.time_domain, sp = m.magnification.spectral;
      chart('r' + ri + '-factor', o.map(function(e){ return [e.order, e.significant ? pos(e.factor) : null, pos(td), pos(sp)]; }),
        ['order', 'a per significant order', 'a, time domain', 'a, spectral (band)'],
        {logscale: true, drawPoints: true, pointSize: 3, strokeWidth: 1, colors: ['#E69F00', '#0072B2', '#009E73'],
         series: {'a, time domain': {strokePattern: [6, 3], drawPoints: false}, 'a, spectral (band)': {strokePattern: [2, 3], drawPoints: false}},
         xlabel: 'crank order (per turn)', ylabel: 'a (model / measured)'});
    }
    if (rec.spectra && document.getElementById('r' + ri + '-spectrum')){
      var keys = Object.keys(rec.spectra), ax = rec.spectra[keys[0]].order;
      chart('r' + ri + '-spectrum', ax.map(function(ov, i){ return [ov].concat(keys.map(function(k){ var v = rec.spectra[k].amplitude[i]; return v > 0 ? v : null; })); }),
        ['order'].concat(keys.map(function(k){ return 'measured ' + name(k).symbol + ' (before the filter)'; })),
        {logscale: true, strokeWidth: 1, colors: [colors.measured, '#E69F00'], xlabel: 'crank order (per turn)',
         ylabel: 'amplitude (' + name(keys[0]).unit + ')'});
    }
  });
