// Per recording, the technician's views (report/views_record.hpp): the raw
// signal around the middle of the recording with the detected pulses, the
// crank speed over the recording, and the revolution × crank-angle map of the
// deviation from the nominal response (a canvas, counted like the charts).
  var viewColors = ['#0072B2', '#D55E00', '#009E73', '#CC79A7', '#E69F00', '#56B4E9'];
  function viewReady(div, finite){
    div.setAttribute('data-drawn', finite);
    if (finite === 0) recordError('chart ' + div.id + ' has no data');
    drawn++;
    allDrawn();
  }
  function timeMarkers(x){
    return function(ctx, area, g){
      function lines(times, color, dash){
        ctx.save(); ctx.strokeStyle = color; ctx.lineWidth = 1; ctx.setLineDash(dash);
        times.forEach(function(t){ var px = g.toDomXCoord(t); ctx.beginPath(); ctx.moveTo(px, area.y); ctx.lineTo(px, area.y + area.h); ctx.stroke(); });
        ctx.restore();
      }
      lines(x.removed_edge_s || [], '#9aa7b4', [2, 2]);
      lines(x.wheel_edge_s || [], 'rgba(0,0,0,0.12)', []);
      lines(x.pulse_s.filter(function(t, i){ return !x.pulse_inserted[i]; }), '#000', []);
      lines(x.pulse_s.filter(function(t, i){ return x.pulse_inserted[i]; }), '#000', [6, 4]);
    };
  }
  // Counts packed little-endian in base64 (report/packed_numbers.hpp) × their step.
  function unpack(b64, bytes, step){
    var bin = atob(b64), n = Math.floor(bin.length / bytes), out = new Array(n);
    for (var i = 0; i < n; i++){
      var u = 0; for (var b = 0; b < bytes; b++) u |= bin.charCodeAt(i * bytes + b) << (8 * b);
      var shift = 32 - 8 * bytes; out[i] = (u << shift >> shift) * step;
    }
    return out;
  }
  function excerptCharts(rec, id){
    var x = rec.views.excerpt, t = [];
    for (var k = 0; k < x.points; k++) t.push(x.time_first_s + k * x.time_step_s);
    x.traces.forEach(function(tr){ tr.values = unpack(tr.values_int16_base64, 2, tr.unit_per_count); });
    var angle = x.traces.filter(function(tr){ return tr.unit === 'V'; });
    var accel = x.traces.filter(function(tr){ return tr.unit !== 'V'; });
    if (document.getElementById(id + 'pulse') && angle.length){
      var th = x.thresholds, absolute = !th.follows_baseline;
      var labels = ['time (s)'].concat(angle.map(function(tr){ return tr.name + ' (V)'; }));
      if (absolute) labels = labels.concat(['low threshold (V)', 'high threshold (V)']);
      chart(id + 'pulse', t.map(function(tv, i){
        var row = [tv].concat(angle.map(function(tr){ return tr.values[i]; }));
        return absolute ? row.concat([th.low_V, th.high_V]) : row; }), labels,
        {colors: viewColors.slice(0, angle.length).concat(['#8a6d00', '#8a6d00']), strokeWidth: 1.2,
         series: {'low threshold (V)': {strokePattern: [4, 3]}, 'high threshold (V)': {strokePattern: [8, 3]}},
         underlayCallback: timeMarkers(x), xlabel: 'time (s)', ylabel: 'crank signal (V)'});
    }
    if (document.getElementById(id + 'accel') && accel.length){
      chart(id + 'accel', t.map(function(tv, i){ return [tv].concat(accel.map(function(tr){ return tr.values[i]; })); }),
        ['time (s)'].concat(accel.map(function(tr){ return tr.name + ' (m/s²)'; })),
        {colors: viewColors.slice(0, accel.length), strokeWidth: 1, underlayCallback: timeMarkers(x),
         xlabel: 'time (s)', ylabel: 'calibrated reading (m/s²)'});
    }
  }
  function speedChart(rec, id){
    var s = rec.views.speed, rows = [], grouped = s.revolutions_per_point > 1;
    s.time_s.forEach(function(tv, i){
      if (i > 0 && s.segment[i] !== s.segment[i - 1]) rows.push([tv, null, null]);
      var v = grouped ? [s.rpm_min[i], s.rpm[i], s.rpm_max[i]] : s.rpm[i];
      var mean = grouped ? [s.mean_rpm, s.mean_rpm, s.mean_rpm] : s.mean_rpm;
      rows.push([tv, v, mean]);
    });
    chart(id + 'speed', rows, ['time (s)', grouped ? 'crank speed (mean, min–max of each group)' : 'crank speed per revolution', 'mean of the recording'],
      {customBars: grouped, connectSeparatedPoints: false, drawPoints: s.rpm.length <= 200, pointSize: 2, strokeWidth: 1.2,
       colors: [viewColors[0], '#5b6875'], series: {'mean of the recording': {strokePattern: [6, 3]}},
       xlabel: 'time from the start of the recording (s)', ylabel: 'crank speed (rpm)'});
  }
  // ColorBrewer RdBu (colour-blind safe), blue for negative, red for positive.
  var diverging = ['#053061', '#2166ac', '#4393c3', '#92c5de', '#d1e5f0', '#f7f7f7', '#fddbc7', '#f4a582', '#d6604d', '#b2182b', '#67001f'];
  function divergingRgb(u){  // u in [-1, 1]
    var p = (Math.max(-1, Math.min(1, u)) + 1) / 2 * (diverging.length - 1), i = Math.min(Math.floor(p), diverging.length - 2), f = p - i;
    function c(hex, k){ return parseInt(hex.substr(1 + 2 * k, 2), 16); }
    return [0, 1, 2].map(function(k){ return Math.round(c(diverging[i], k) * (1 - f) + c(diverging[i + 1], k) * f); });
  }
  function mapChart(rec, id){
    var m = rec.views.map, div = document.getElementById(id + 'map'); if (!div) return;
    var counts = unpack(m.deviation_int8_base64, 1, 1), n = counts.length;
    var NR = m.rows, C = m.columns, step = m.rad_s2_per_count;
    // Colour range: ± the 99th percentile of |deviation| (beyond it, the bar's end colours).
    var mags = counts.map(Math.abs).sort(function(a, b){ return a - b; });
    var limit = Math.max(1, mags[Math.min(n - 1, Math.floor(0.99 * n))]) * step;
    var W = Math.max(480, Math.min(div.clientWidth || 900, 1100)), left = 64, right = 96, top = 8, bottom = 44;
    var H = top + bottom + Math.max(140, Math.min(420, 3 * NR));
    var cv = document.createElement('canvas'); cv.width = W; cv.height = H; cv.style.maxWidth = '100%';
    cv.setAttribute('role', 'img'); cv.setAttribute('aria-label', 'deviation map, ' + NR + " revolutions × " + C + ' crank angles');
    div.appendChild(cv);
    var ctx = cv.getContext('2d'), pw = W - left - right, ph = H - top - bottom;
    var img = ctx.createImageData(C, NR), finite = 0;
    for (var r = 0; r < NR; r++) for (var c = 0; c < C; c++){
      var v = counts[r * C + c] * step, rgb = divergingRgb(v / limit), o = 4 * (r * C + c);
      img.data[o] = rgb[0]; img.data[o + 1] = rgb[1]; img.data[o + 2] = rgb[2]; img.data[o + 3] = 255; if (isFinite(v)) finite++;
    }
    var off = document.createElement('canvas'); off.width = C; off.height = NR; off.getContext('2d').putImageData(img, 0, 0);
    ctx.imageSmoothingEnabled = false; ctx.drawImage(off, left, top, pw, ph);
    ctx.strokeStyle = '#5b6875'; ctx.strokeRect(left + 0.5, top + 0.5, pw, ph);
    ctx.fillStyle = '#1c2430'; ctx.font = '11px system-ui, sans-serif'; ctx.textAlign = 'center'; ctx.textBaseline = 'top';
    var norm = function(d){ return Math.round(((d % 360) + 360) % 360); }, first = norm(m.first_crank_deg);
    for (var k = 0; k <= 8; k++){  // x: every 45° turned from the pulse, labelled with θ2
      var px = left + pw * k / 8, label = norm(m.first_crank_deg + m.crank_direction * 45 * k);
      if (k === 8 && label === first) label = first === 0 ? 360 : first;
      ctx.fillRect(px, top + ph, 1, 4); ctx.fillText(String(label), px, top + ph + 6);
    }
    ctx.fillText('crank angle θ2 (deg)', left + pw / 2, top + ph + 24);
    ctx.textAlign = 'right'; ctx.textBaseline = 'middle';
    var yt = Math.min(NR, 6);
    for (var j = 0; j < yt; j++){
      var row = Math.round(j * (NR - 1) / Math.max(1, yt - 1)), py = top + (row + 0.5) * ph / NR;
      ctx.fillRect(left - 4, py, 4, 1); ctx.fillText(String(m.revolution[row]), left - 6, py);
    }
    ctx.save(); ctx.translate(14, top + ph / 2); ctx.rotate(-Math.PI / 2); ctx.textAlign = 'center';
    ctx.fillText('revolution no.', 0, 0); ctx.restore();
    // Colour bar.
    var bx = W - right + 18, bw = 14;
    for (var yb = 0; yb < ph; yb++){ var rgb2 = divergingRgb(1 - 2 * yb / (ph - 1)); ctx.fillStyle = 'rgb(' + rgb2.join(',') + ')'; ctx.fillRect(bx, top + yb, bw, 1); }
    ctx.strokeStyle = '#5b6875'; ctx.strokeRect(bx + 0.5, top + 0.5, bw, ph);
    ctx.fillStyle = '#1c2430'; ctx.textAlign = 'left';
    [1, 0.5, 0, -0.5, -1].forEach(function(u){
      var py = top + (1 - u) / 2 * ph, val = u * limit;
      ctx.fillText((u === 1 ? '≥ ' : u === -1 ? '≤ ' : '') + String(Number(val.toPrecision(2))), bx + bw + 4, py);
    });
    ctx.save(); ctx.translate(W - 8, top + ph / 2); ctx.rotate(-Math.PI / 2); ctx.textAlign = 'center';
    ctx.fillText((m.quantity === 'alpha3_rad_s2' ? 'α3' : 'α4') + ' − nominal (rad/s²)', 0, 0); ctx.restore();
    viewReady(div, finite);
  }
  R.recordings.forEach(function(rec, ri){
    if (!rec.views) return;
    var id = 'r' + ri + '-view-';
    [[excerptCharts, rec.views.excerpt], [speedChart, rec.views.speed], [mapChart, rec.views.map]].forEach(function(v){
      if (!v[1]) return;
      try { v[0](rec, id); } catch (e) { recordError('view ' + id + ': ' + e); }
    });
  });
