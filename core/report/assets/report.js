// Builds report.html from its embedded data (the JSON in #report-data,
// written by unimap's report builder): headline figures, the 3D view, the
// plots (dygraphs), metrics, the run's settings, parameters and messages.
// window.unimapReport exposes the viewer and the plots (the browser test
// reads them) and .ready once everything is drawn.
/* global Dygraph, UnimapViewer */
(function () {
  'use strict';

  const report = {ready: false, viewer: null, plots: {}, data: null};
  window.unimapReport = report;
  const data = JSON.parse(document.getElementById('report-data').textContent);
  report.data = data;
  const root = document.getElementById('report');

  // A float32 table (base64 of little-endian bytes) as a Float32Array.
  function decode(base64) {
    const text = atob(base64 || '');
    const bytes = new Uint8Array(text.length);
    for (let i = 0; i < text.length; ++i) bytes[i] = text.charCodeAt(i);
    return new Float32Array(bytes.buffer);
  }

  // el('tag.class', {attributes}, children...): children are nodes or text.
  function el(spec, attributes, ...children) {
    const [tag, ...classes] = spec.split('.');
    const node = document.createElement(tag);
    if (classes.length) node.className = classes.join(' ');
    for (const [key, value] of Object.entries(attributes || {})) node.setAttribute(key, value);
    for (const child of children) {
      if (child !== null && child !== undefined) node.append(child instanceof Node ? child : String(child));
    }
    return node;
  }

  function section(title, id, ...children) {
    const s = el('section', {id: id}, el('h2', {}, title), ...children);
    root.append(s);
    return s;
  }

  function valueWithUnit(row) {
    return row.unit && row.value !== 'n/a' && row.value !== '' ? row.value + ' ' + row.unit : row.value;
  }

  function format(v, digits) {
    return Number.isFinite(v) ? v.toFixed(digits) : 'n/a';
  }

  // Header: title, folder, notes, headline cards.
  function header() {
    root.append(el('h1', {}, data.title), el('p.folder', {}, 'Run folder: ', el('code', {}, data.folder)));
    for (const note of data.notes || []) root.append(el('p.note', {}, note));
    const cards = el('div.cards');
    for (const card of data.cards || []) {
      cards.append(el('div.card', {title: card.key}, el('div.card-value', {}, valueWithUnit(card)),
                      el('div.card-label', {}, card.label)));
    }
    root.append(cards);
  }

  function viewerSection() {
    if (!data.map && !(data.trajectories || []).length) return;
    const canvasBox = el('div.viewer-canvas');
    const hover = el('div.viewer-hover', {}, 'Hover over a trajectory for its time and position.');
    const legend = el('div.legend');
    const status = el('div.viewer-status');
    const toolbar = el('div.viewer-toolbar');
    section('Map and trajectories', 'map-view',
            el('p.hint', {}, 'Drag to orbit (3D) or pan (top / side), right-drag to pan, wheel to zoom.'),
            toolbar, canvasBox, el('div.viewer-footer', {}, legend, status, hover));
    const map = data.map ? {xyz: decode(data.map.xyz), shown: data.map.shown,
                            intensity: data.map.intensity ? decode(data.map.intensity) : null,
                            error: data.map.error ? decode(data.map.error) : null} : null;
    const trajectories = (data.trajectories || []).map(t => Object.assign({}, t, {txyz: decode(t.txyz)}));
    const loops = data.loops && data.loops.count > 0 ? {xyz: decode(data.loops.xyz)} : null;
    let viewer;
    try {
      viewer = new UnimapViewer(canvasBox, {map: map, trajectories: trajectories, loops: loops});
    } catch (e) {
      canvasBox.append(el('p.note', {}, 'The 3D view needs WebGL: ' + e.message));
      console.error('unimap report: no 3D view: ' + e.message);
      return;
    }
    report.viewer = viewer;

    for (const [view, label] of [['3d', '3D'], ['top', 'Top (x-y)'], ['side', 'Side (x-z)']]) {
      const button = el('button', {type: 'button', 'data-view': view}, label);
      button.addEventListener('click', () => viewer.setView(view));
      toolbar.append(button);
    }
    if (map) {
      const select = el('select', {'aria-label': 'colour map by'});
      select.append(el('option', {value: 'height'}, 'colour: height'));
      select.append(el('option', map.intensity ? {value: 'intensity'} : {value: 'intensity', disabled: ''},
                       map.intensity ? 'colour: intensity' : 'colour: intensity (none in the map)'));
      select.append(el('option', map.error ? {value: 'error'} : {value: 'error', disabled: ''},
                       map.error ? 'colour: map error' : 'colour: map error (' + data.map.error_note + ')'));
      const recolor = () => drawLegend(legend, viewer.colorBy(select.value));
      select.addEventListener('change', recolor);
      toolbar.append(select);
      const size = el('input', {type: 'range', min: '1', max: '6', step: '0.5', value: '2', 'aria-label': 'point size'});
      size.addEventListener('input', () => viewer.setPointSize(Number(size.value)));
      toolbar.append(el('label', {}, 'point size ', size));
      const zmin = viewer.bounds.min.z, zmax = viewer.bounds.max.z;
      const cut = el('input', {type: 'range', min: String(zmin), max: String(zmax), step: String((zmax - zmin) / 100),
                               value: String(zmax), 'aria-label': 'hide the map above this height'});
      const cutValue = el('span.num', {}, 'off');
      cut.addEventListener('input', () => {
        const z = Number(cut.value);
        viewer.setHeightCut(z >= zmax ? Infinity : z);
        cutValue.textContent = z >= zmax ? 'off' : format(z, 2) + ' m';
      });
      toolbar.append(el('label', {}, 'hide above ', cut, ' ', cutValue));
      report.setHeightCut = (fraction) => {  // 0..1 of the height range, from scripts (the README screenshot)
        cut.value = String(zmin + fraction * (zmax - zmin));
        cut.dispatchEvent(new Event('input'));
      };
      recolor();
    }
    const layerNames = [].concat(map ? [['map', 'map']] : [], trajectories.map(t => [t.name, t.label]),
                                 loops ? [['loops', data.loops.count + ' loop closures']] : [], [['grid', 'grid']]);
    for (const [name, label] of layerNames) {
      const box = el('input', {type: 'checkbox', checked: ''});
      box.addEventListener('change', () => viewer.setVisible(name, box.checked));
      const colour = (trajectories.find(t => t.name === name) || {}).color;
      toolbar.append(el('label.layer', {}, box, colour ? el('span.swatch', {style: 'background:' + colour}) : null,
                        label));
    }
    const parts = [];
    if (data.map) {
      parts.push(data.map.shown === data.map.total
        ? 'all ' + data.map.total.toLocaleString('en-US') + ' map points shown'
        : data.map.shown.toLocaleString('en-US') + ' of ' + data.map.total.toLocaleString('en-US') +
          ' map points shown (one in ' + Math.ceil(data.map.total / data.map.shown) + ')');
    }
    parts.push('grid cells ' + viewer.gridCellM + ' m');
    status.textContent = parts.join(' · ');
    let pending = null;
    viewer.renderer.domElement.addEventListener('mousemove', (event) => {
      if (pending) return;
      pending = window.requestAnimationFrame(() => {
        pending = null;
        const rect = viewer.renderer.domElement.getBoundingClientRect();
        const hit = viewer.pick(event.clientX - rect.left, event.clientY - rect.top, 12);
        hover.textContent = hit ? hit.trajectory + ': t = ' + format(hit.t, 2) + ' s, x = ' + format(hit.x, 3) +
          ' m, y = ' + format(hit.y, 3) + ' m, z = ' + format(hit.z, 3) + ' m' : '';
      });
    });
  }

  function drawLegend(legend, range) {
    legend.textContent = '';
    if (!range) return;
    const canvas = el('canvas', {width: '160', height: '12'});
    const ctx = canvas.getContext('2d');
    const rgb = [0, 0, 0];
    for (let x = 0; x < 160; ++x) {
      UnimapViewer.rampColor(range.ramp, x / 159, rgb, 0);
      ctx.fillStyle = 'rgb(' + rgb.map(c => Math.round(255 * c)).join(',') + ')';
      ctx.fillRect(x, 0, 1, 12);
    }
    const unit = range.unit ? ' ' + range.unit : '';
    legend.append(format(range.lo, 2) + unit + ' ', canvas, ' ' + format(range.hi, 2) + unit);
  }

  function plotsSection() {
    if (!(data.plots || []).length) return;
    const s = section('Plots', 'plots', el('p.hint', {},
      'Drag to zoom, double-click to zoom out, hover for values. Time in seconds since the first pose.'));
    for (const plot of data.plots) {
      const values = decode(plot.data);
      const columns = plot.labels.length;
      const rows = [];
      for (let r = 0; r < plot.rows; ++r) rows.push(Array.from(values.subarray(r * columns, (r + 1) * columns)));
      const chart = el('div.plot');
      const labels = el('div.plot-labels');
      s.append(el('h3', {}, plot.title), chart, labels);
      const series = {};
      plot.labels.slice(1).forEach((label, i) => {
        series[label] = {strokePattern: plot.dashed[i] ? Dygraph.DASHED_LINE : null};
      });
      report.plots[plot.id] = new Dygraph(chart, rows, {
        labels: plot.labels, colors: plot.colors, series: series, xlabel: 'time since start [s]',
        ylabel: plot.ylabel, labelsDiv: labels, legend: 'always', strokeWidth: 1.3, digitsAfterDecimal: 4,
        labelsSeparateLines: false, animatedZooms: false,
      });
    }
  }

  function table(head, rows) {
    const t = el('table', {}, el('thead', {}, el('tr', {}, ...head.map(h => el('th', {}, h)))));
    const body = el('tbody');
    for (const row of rows) body.append(el('tr', {}, ...row.map(c => c instanceof Node ? el('td', {}, c) : el('td', {}, c))));
    t.append(body);
    return t;
  }

  function labelCell(row) {
    return el('span', {}, row.label, el('br'), el('code.key', {}, row.key));
  }

  function tablesSection() {
    if ((data.metrics || []).length) {
      section('Metrics', 'metrics', el('p.hint', {}, 'Definitions: docs/evaluation.md; full precision in metrics.json.'),
              table(['metric', 'value', 'meaning'],
                    data.metrics.map(m => [labelCell(m), el('span.num', {}, valueWithUnit(m)), m.meaning])));
    }
    if ((data.sections || []).length) {
      const grid = el('div.sections');
      for (const s of data.sections) {
        grid.append(el('div.run-section', {}, el('h3', {}, s.title),
                       table(['', ''], s.rows.map(r => [labelCell(r), el('span.num', {}, valueWithUnit(r))]))));
      }
      section('Run', 'run', grid);
    }
    if ((data.parameters || []).length) {
      section('Effective parameters', 'parameters', table(['key', 'symbol', 'value', 'source', 'meaning'],
        data.parameters.map(p => [el('code', {}, p.key), p.symbol, el('span.num', {}, p.value), p.source, p.meaning])));
    }
    const messages = data.messages || [];
    section('Warnings and skipped items', 'messages', messages.length
      ? el('ul', {}, ...messages.map(m => el('li', {}, el('code.key', {}, m.source), ' ', m.text)))
      : el('p', {}, 'None.'));
    if ((data.files || []).length) {
      section('Files', 'files', table(['', 'path'], data.files.map(f => [f.label, el('code', {}, f.path)])));
    }
  }

  header();
  viewerSection();
  plotsSection();
  tablesSection();
  report.ready = true;
})();
