// Shared by every chart script: script-error capture (read by the browser
// test), the report data R, the palette and the names of the quantities,
// number formatting for axes, and chart() which draws one dygraph, counts it
// and redraws it at the paper's width when the page is printed.
  var errors = [];
  function recordError(msg){ errors.push(String(msg)); document.body.setAttribute('data-js-errors', errors.length);
    var box = document.getElementById('js-errors'); box.style.display='block';
    var li = document.createElement('li'); li.textContent = String(msg); box.querySelector('ul').appendChild(li); }
  window.addEventListener('error', function(e){ recordError(e.message || e); });
  document.addEventListener('securitypolicyviolation', function(e){ recordError('blocked request: ' + e.blockedURI); });
  var origError = console.error; console.error = function(){ recordError(Array.prototype.join.call(arguments,' ')); origError.apply(console, arguments); };
  document.body.setAttribute('data-js-errors', 0);

  var R = JSON.parse(document.getElementById('report-data').textContent);

  // Okabe–Ito colours (safe for the common colour-vision deficiencies). One
  // colour per role on every chart; the recordings take the others in turn.
  var colors = {measured:'#0072B2', clearance:'#D55E00', nominal:'#000000', modified:'#CC79A7', floor:'#999999'};
  var recordingPalette = ['#E69F00', '#56B4E9', '#009E73', '#CC79A7', '#F0E442', '#0072B2', '#D55E00', '#000000'];
  function recordingColor(i){ return recordingPalette[i % recordingPalette.length]; }
  var recordingIndex = {};
  R.recordings.forEach(function(r, i){ recordingIndex[r.name] = i; });
  Array.prototype.forEach.call(document.querySelectorAll('.swatch[data-rec]'), function(s){
    s.style.background = recordingColor(+s.getAttribute('data-rec')); });

  // Names a person reads, from the same table as the report's tables
  // (report/quantity_names.cpp): name(k).label = "coupler angular acceleration α3 (rad/s²)".
  function name(k){ return R.names[k] || {symbol: k, description: k, unit: '', label: k, axis: k}; }

  // Axis numbers: shortest text that tells the tick apart, never cut; powers
  // of ten as 1e-3 on log axes and for very small or large values.
  function shortNumber(v){
    if (v === 0) return '0';
    var a = Math.abs(v);
    if (a >= 1e-3 && a < 1e5) return String(parseFloat(v.toPrecision(6)));
    var e = v.toExponential(3).split('e'), m = String(parseFloat(e[0]));
    return m + 'e' + (+e[1]);
  }
  function axisNumber(v){ return shortNumber(v).replace(/-/g, '−'); }
  // Log axes: ticks at 1, 2, 5 × 10^k only, labelled at the powers of ten (and
  // the 2 and 5 when the axis spans less than three decades).
  function logTicks(min, max, pixels, opts, g){
    if (!(min > 0) || !(max > min)) return Dygraph.numericTicks(min, max, pixels, opts, g);
    var ticks = [], lo = Math.floor(Math.log10(min)), hi = Math.ceil(Math.log10(max)), few = hi - lo < 3;
    for (var k = lo; k <= hi; k++) [1, 2, 5].forEach(function(m){ var v = m * Math.pow(10, k);
      if (v >= min * 0.999 && v <= max * 1.001) ticks.push({v: v, label: (m === 1 || few) ? axisNumber(parseFloat(v.toPrecision(3))) : ''}); });
    if (ticks.filter(function(t){ return t.label; }).length < 2) return Dygraph.numericTicks(min, max, pixels, opts, g);
    return ticks;
  }
  var axisStyle = {
    x: {axisLabelFormatter: axisNumber, valueFormatter: shortNumber, pixelsPerLabel: 60},
    y: {axisLabelFormatter: axisNumber, valueFormatter: shortNumber, axisLabelWidth: 62, pixelsPerLabel: 28},
    y2: {axisLabelFormatter: axisNumber, valueFormatter: shortNumber, axisLabelWidth: 62, pixelsPerLabel: 28, independentTicks: true}};

  var graphs = [], drawn = 0, scriptsDone = false;
  function allDrawn(){
    var expected = document.querySelectorAll('div.chart').length;
    if (scriptsDone && drawn === expected) document.body.setAttribute('data-charts-drawn', drawn);
  }
  function ready(div, g){
    if (div.getAttribute('data-drawn')) return;
    var rows = g.numRows(), finite = 0;
    for (var i = 0; i < rows; i++) for (var c = 1; c < g.numColumns(); c++) { var v = g.getValue(i, c);
      if (Array.isArray(v)) v = v[1]; if (v !== null && isFinite(v)) { finite++; break; } }
    div.setAttribute('data-drawn', finite);
    if (finite === 0) recordError('chart ' + div.id + ' has no data');
    drawn++;
    allDrawn();
  }
  function toggles(div, g, labels){
    var box = document.getElementById(div.id + '-controls'); if (!box) return;
    labels.slice(1).forEach(function(l, i){
      var lab = document.createElement('label'), cb = document.createElement('input');
      cb.type = 'checkbox'; cb.checked = true; cb.onchange = function(){ g.setVisibility(i, cb.checked); };
      lab.appendChild(cb); lab.appendChild(document.createTextNode(' ' + l)); box.appendChild(lab); });
  }
  function chart(id, data, labels, opts){
    var div = document.getElementById(id);
    var base = {labels: labels, legend: 'always', labelsDiv: id + '-legend', labelsSeparateLines: false,
      highlightSeriesOpts: null, animatedZooms: false, connectSeparatedPoints: true, yLabelWidth: 20, xLabelHeight: 20,
      axisLabelFontSize: 12, drawCallback: function(g, initial){ if (initial) ready(div, g); }};
    for (var k in opts) if (k !== 'axes') base[k] = opts[k];
    base.axes = {};
    ['x', 'y', 'y2'].forEach(function(a){ var o = {}, k;
      for (k in axisStyle[a]) o[k] = axisStyle[a][k];
      if (opts.logscale && a !== 'x') o.ticker = logTicks;
      if (opts.axes && opts.axes[a]) for (k in opts.axes[a]) o[k] = opts.axes[a][k];
      base.axes[a] = o; });
    var g = new Dygraph(div, data, base);
    graphs.push(g);
    toggles(div, g, labels);
    return g;
  }
  // A chart box whose data cannot make a chart (one point) shows a table instead.
  function tableInstead(id, head, rows){
    var div = document.getElementById(id); if (!div) return;
    var t = document.createElement('table'); t.className = 'chart-table';
    var tr = t.insertRow(); head.forEach(function(h){ var th = document.createElement('th'); th.textContent = h; tr.appendChild(th); });
    rows.forEach(function(r){ var row = t.insertRow(); r.forEach(function(v){ var td = row.insertCell();
      if (v && v.swatch !== undefined){ var s = document.createElement('span'); s.className = 'swatch'; s.style.background = recordingColor(v.swatch);
        td.appendChild(s); td.appendChild(document.createTextNode(v.text)); td.className = 'l'; }
      else td.textContent = (typeof v === 'number') ? shortNumber(v) : (v === null || v === undefined ? '–' : v); }); });
    div.parentNode.replaceChild(t, div);
    var c = document.getElementById(id + '-controls'); if (c) c.parentNode.removeChild(c);
  }

  // Printing: the canvases have the screen's width. When the print media
  // applies, each chart is redrawn at the paper's width (the print CSS gives
  // the boxes the page width) at twice the resolution, and shown through an
  // image of its canvas: Chromium prints a canvas that was redrawn while
  // printing as blank, an image of it as drawn. Back to the screen after.
  function forPrint(on){
    graphs.forEach(function(g){
      var old = g.graphDiv.querySelector('img.print-snapshot'); if (old) old.remove();
      if (g.rangeSelectorOnScreen === undefined) g.rangeSelectorOnScreen = !!g.getOption('showRangeSelector');
      g.updateOptions({pixelRatio: on ? 2 : null, showRangeSelector: g.rangeSelectorOnScreen && !on}, true);
      g.resize();
      if (!on) return;
      var img = document.createElement('img'); img.className = 'print-snapshot'; img.alt = '';
      img.src = g.hidden_.toDataURL('image/png');
      img.style.cssText = 'position:absolute;left:0;top:0;width:' + g.width_ + 'px;height:' + g.height_ + 'px';
      g.graphDiv.appendChild(img); });
  }
  if (window.matchMedia){ var printMedia = window.matchMedia('print');
    var onPrint = function(e){ forPrint(e.matches); };
    if (printMedia.addEventListener) printMedia.addEventListener('change', onPrint); else printMedia.addListener(onPrint); }
