// "Fitted bearing parameters": the objective's profiles per parameter, and
// per recording the averaged measured curve against the model at the prior
// and at the fitted contact parameters.
  if (R.fit) (function(F){
    function profiles(f, prefix){
      Object.keys(f.parameters).forEach(function(p){
        var P = f.parameters[p], id = prefix + p;
        if (!P.profile || !document.getElementById(id)) return;
        var pts = P.profile.slice().sort(function(a, b){ return a[0] - b[0]; });
        var lowest = Math.min.apply(null, pts.map(function(q){ return q[1]; })), lim = lowest + f.interval_delta_chi2;
        chart(id, pts.map(function(q){ return [q[0], q[1], lim, q[0] >= P.low && q[0] <= P.high ? q[1] : null]; }),
          [p, 'χ² (lowest over the other parameter)', 'lowest + Δχ²', 'inside the interval'],
          {drawPoints: true, pointSize: 3, strokeWidth: 1.2, colors: ['#34495e', '#9aa7b4', '#c0392b'],
           xlabel: p, ylabel: 'χ²', logscale: true});
      });
    }
    if (F.session_fit) profiles(F.session_fit, 'fit-profile-');
    (F.per_recording || []).forEach(function(f, i){ profiles(f, 'fit-profile-' + i + '-'); });
    R.recordings.forEach(function(rec, ri){
      var id = 'fit-r' + ri; if (!document.getElementById(id) || !rec.fitted_theory) return;
      var q = rec.series.alpha3_rad_s2 && rec.series.alpha3_rad_s2.measured ? 'alpha3_rad_s2' : 'alpha4_rad_s2';
      var s = rec.series[q], f = rec.fitted_theory.series[q], x = rec.grid.crank_deg;
      chart(id, x.map(function(xv, i){ return [xv, s.measured[i], s.clearance[i], f.clearance[i], s.nominal[i]]; }),
        ['crank angle (deg)', 'measured (mean)', 'model at the prior (mean)', 'model at the fitted values (mean)', 'nominal'],
        {strokeWidth: 1.1, colors: ['#1f5fbf', '#c0392b', '#e67e22', '#2e7d32'],
         xlabel: 'crank angle θ2 (deg)', ylabel: (q === 'alpha3_rad_s2' ? 'α3' : 'α4') + ' (rad/s²)'});
    });
  })(R.fit);
