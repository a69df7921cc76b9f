// Shared by every chart script: script-error capture (read by the browser
// test), the report data R, and chart() which draws one dygraph and counts it.
  var errors = [];
  function recordError(msg){ errors.push(String(msg)); document.body.setAttribute('data-js-errors', errors.length);
    var box = document.getElementById('js-errors'); box.style.display='block';
    var li = document.createElement('li'); li.textContent = String(msg); box.querySelector('ul').appendChild(li); }
  window.addEventListener('error', function(e){ recordError(e.message || e); });
  document.addEventListener('securitypolicyviolation', function(e){ recordError('blocked request: ' + e.blockedURI); });
  var origError = console.error; console.error = function(){ recordError(Array.prototype.join.call(arguments,' ')); origError.apply(console, arguments); };
  document.body.setAttribute('data-js-errors', 0);

  var R = JSON.parse(document.getElementById('report-data').textContent);
  var expected = document.querySelectorAll('div.chart').length, drawn = 0;
  function ready(div, g){
    if (div.getAttribute('data-drawn')) return;
    var rows = g.numRows(), finite = 0;
    for (var i = 0; i < rows; i++) for (var c = 1; c < g.numColumns(); c++) { var v = g.getValue(i, c);
      if (Array.isArray(v)) v = v[1]; if (v !== null && isFinite(v)) { finite++; break; } }
    div.setAttribute('data-drawn', finite);
    if (finite === 0) recordError('chart ' + div.id + ' has no data');
    drawn++;
    if (drawn === expected) document.body.setAttribute('data-charts-drawn', drawn);
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
      highlightSeriesOpts: null, animatedZooms: false, connectSeparatedPoints: true,
      drawCallback: function(g, initial){ if (initial) ready(div, g); }};
    for (var k in opts) base[k] = opts[k];
    var g = new Dygraph(div, data, base);
    toggles(div, g, labels);
    return g;
  }
