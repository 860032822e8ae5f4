// hotlap report: draws every chart described by the JSON in #hotlap-data with Chart.js, then
// reports in #hotlap-status how many were drawn (the tests read it; see report_errors.js).
//
// Data: {"charts": [spec, ...], "arrays": [[numbers], ...]}; a spec refers to its data by index
// into "arrays" (identical arrays are stored once). null in an array is a gap.
(function () {
  'use strict';
  const report = window.hotlapReport;
  const data = JSON.parse(document.getElementById('hotlap-data').textContent);
  const arrays = data.arrays;
  const EVENTS = ['mousemove', 'mouseout', 'click', 'touchstart', 'touchmove', 'touchend',
    'mousedown', 'mouseup', 'dblclick'];
  const VIRIDIS = [[68, 1, 84], [72, 40, 120], [62, 74, 137], [49, 104, 142], [38, 130, 142],
    [31, 158, 137], [53, 183, 121], [109, 205, 89], [180, 222, 44], [253, 231, 37]];

  Chart.defaults.font.family = 'system-ui, -apple-system, "Segoe UI", Roboto, sans-serif';
  Chart.defaults.font.size = 11;
  Chart.defaults.color = '#333';
  Chart.defaults.animation = false;
  // Also the drag-zoom events; a plugin sees the default list, not the chart's `events` option.
  Chart.defaults.events = EVENTS;

  const fmt = (v) => (typeof v === 'number' && isFinite(v) ? String(Number(v.toPrecision(5))) : '-');
  const given = (v) => (v === null ? undefined : v);
  const num = (v) => (v === null ? NaN : v);

  function points(xs, ys) {
    const out = new Array(xs.length);
    for (let i = 0; i < xs.length; ++i) out[i] = { x: num(xs[i]), y: num(ys[i]) };
    return out;
  }

  function finiteRange(values) {
    let lo = Infinity, hi = -Infinity;
    for (const v of values) {
      if (v !== null && isFinite(v)) { lo = Math.min(lo, v); hi = Math.max(hi, v); }
    }
    return lo <= hi ? [lo, hi] : [0, 1];
  }

  function viridis(t) {
    const s = Math.min(1, Math.max(0, isFinite(t) ? t : 0)) * (VIRIDIS.length - 1);
    const i = Math.min(Math.floor(s), VIRIDIS.length - 2), f = s - i;
    const a = VIRIDIS[i], b = VIRIDIS[i + 1];
    return 'rgb(' + [0, 1, 2].map((k) => Math.round(a[k] + f * (b[k] - a[k]))).join(',') + ')';
  }

  function axis(spec, fixed) {
    return {
      type: 'linear',
      min: fixed ? given(spec.min) : undefined,
      max: fixed ? given(spec.max) : undefined,
      title: { display: spec.title !== '', text: spec.title },
      // A map's range is set for equal scales, not on round numbers: no ticks at its ends.
      ticks: { maxRotation: 0, includeBounds: fixed, precision: spec.integer ? 0 : undefined },
    };
  }

  // For every series, the point nearest in x to the mouse: one tooltip lists all the lines even
  // where they were thinned at different samples.
  Chart.Interaction.modes.hotlapEachSeries = function (chart, event) {
    const area = chart.chartArea;
    if (!area || event.x < area.left || event.x > area.right) return [];
    const x = chart.scales.x.getValueForPixel(event.x);
    const items = [];
    chart.data.datasets.forEach((dataset, datasetIndex) => {
      const pts = dataset.data;
      if (!chart.isDatasetVisible(datasetIndex) || pts.length === 0) return;
      let lo = 0, hi = pts.length - 1;
      while (hi - lo > 1) {
        const mid = (lo + hi) >> 1;
        if (pts[mid].x < x) lo = mid; else hi = mid;
      }
      const index = Math.abs(pts[lo].x - x) <= Math.abs(pts[hi].x - x) ? lo : hi;
      const element = chart.getDatasetMeta(datasetIndex).data[index];
      if (element && !element.skip) items.push({ element, datasetIndex, index });
    });
    return items;
  };

  // Linked x ranges: drag across a line chart to zoom, double-click to zoom out.
  const links = {};
  function setXRange(chart, lo, hi) {
    for (const c of chart.$link ? links[chart.$link] : [chart]) {
      c.options.scales.x.min = lo === null ? given(c.$spec.x.min) : lo;
      c.options.scales.x.max = hi === null ? given(c.$spec.x.max) : hi;
      c.update('none');
    }
  }
  const dragZoom = {
    id: 'hotlapDragZoom',
    afterEvent(chart, args) {
      // Chart.js replays the last event after every update: ignore that, or a double-click would
      // zoom out forever.
      const e = args.event, area = chart.chartArea;
      if (!area || args.replay) return;
      const inside = e.x >= area.left && e.x <= area.right && e.y >= area.top && e.y <= area.bottom;
      const drag = chart.$drag;
      const clamp = (x) => Math.min(Math.max(x, area.left), area.right);
      if (e.type === 'mousedown' && inside) {
        chart.$drag = { from: e.x, to: e.x };
      } else if (e.type === 'mousemove' && drag) {
        drag.to = clamp(e.x);
        args.changed = true;
      } else if ((e.type === 'mouseup' || e.type === 'mouseout') && drag) {
        chart.$drag = null;
        args.changed = true;
        // Leaving the chart mid-drag zooms to its edge. Chart.js throttles mousemove, so the
        // last one may not have arrived yet: the end is where the button was let go.
        drag.to = clamp(e.x);
        if (Math.abs(drag.to - drag.from) > 4) {
          const scale = chart.scales.x;
          setXRange(chart, scale.getValueForPixel(Math.min(drag.from, drag.to)),
            scale.getValueForPixel(Math.max(drag.from, drag.to)));
        }
      } else if (e.type === 'dblclick' && inside) {
        setXRange(chart, null, null);
      }
    },
    afterDraw(chart) {
      const drag = chart.$drag, area = chart.chartArea;
      if (!drag || drag.to === drag.from) return;
      chart.ctx.save();
      chart.ctx.fillStyle = 'rgba(78, 121, 167, 0.18)';
      chart.ctx.fillRect(Math.min(drag.from, drag.to), area.top, Math.abs(drag.to - drag.from),
        area.bottom - area.top);
      chart.ctx.restore();
    },
  };

  function lineChart(spec, canvas) {
    const datasets = spec.series.map((s) => ({
      label: s.label,
      data: points(arrays[s.x], arrays[s.y]),
      borderColor: s.colour,
      backgroundColor: s.colour,
      borderDash: s.dash,
      borderWidth: 1.5,
      pointRadius: 0,
      pointHoverRadius: 3,
      pointHitRadius: 4,
      tension: 0,
      spanGaps: false,
    }));
    return new Chart(canvas, {
      type: 'line',
      data: { datasets },
      options: {
        responsive: true,
        maintainAspectRatio: false,
        parsing: false,
        normalized: true,
        interaction: { mode: 'hotlapEachSeries', intersect: false },
        plugins: {
          legend: { position: 'top', align: 'end', labels: { boxWidth: 14, boxHeight: 2 } },
          tooltip: {
            callbacks: {
              title: (items) => (items.length ? spec.x.title + ': ' + fmt(items[0].parsed.x) : ''),
              label: (item) => item.dataset.label + ': ' + fmt(item.parsed.y),
            },
          },
        },
        scales: { x: axis(spec.x, true), y: axis(spec.y, true) },
      },
      plugins: [dragZoom],
    });
  }

  // Equal scales on both axes: after each layout, widen the x or the y range so that a metre
  // takes as many pixels across as up, and lay out again (tick labels may change the plot area a
  // little, so up to a few passes).
  const equalAxes = {
    id: 'hotlapEqualAxes',
    afterLayout(chart, args, options) {
      const e = options.extent, a = chart.chartArea;
      if (!e || !a || a.width <= 0 || a.height <= 0) return;
      const perPixel = 1.04 * Math.max((e.x1 - e.x0) / a.width, (e.y1 - e.y0) / a.height, 1e-12);
      const cx = (e.x0 + e.x1) / 2, cy = (e.y0 + e.y1) / 2;
      const hx = perPixel * a.width / 2, hy = perPixel * a.height / 2;
      const sx = chart.options.scales.x, sy = chart.options.scales.y;
      const off = (have, want, range) => have === undefined || Math.abs(have - want) > 1e-3 * range;
      if (off(sx.min, cx - hx, hx) || off(sx.max, cx + hx, hx) || off(sy.min, cy - hy, hy) ||
          off(sy.max, cy + hy, hy)) {
        sx.min = cx - hx; sx.max = cx + hx; sy.min = cy - hy; sy.max = cy + hy;
        chart.$equalPending = true;
      }
    },
    afterRender(chart) {
      if (!chart.$equalPending) return;
      chart.$equalPending = false;
      chart.$equalPasses = (chart.$equalPasses || 0) + 1;
      if (chart.$equalPasses <= 4) chart.update('none');
    },
    resize(chart) { chart.$equalPasses = 0; },
  };

  function colourBar(element, title, lo, hi) {
    const stops = VIRIDIS.map((c, i) =>
      'rgb(' + c.join(',') + ') ' + (100 * i / (VIRIDIS.length - 1)).toFixed(1) + '%');
    const ramp = document.createElement('div');
    ramp.className = 'ramp';
    ramp.style.background = 'linear-gradient(to right, ' + stops.join(', ') + ')';
    const ticks = document.createElement('div');
    ticks.className = 'ticks';
    for (let k = 0; k <= 4; ++k) {
      const tick = document.createElement('span');
      tick.textContent = fmt(lo + (hi - lo) * k / 4);
      ticks.appendChild(tick);
    }
    const label = document.createElement('div');
    label.className = 'label';
    label.textContent = title;
    element.replaceChildren(ramp, ticks, label);
  }

  function mapChart(spec, canvas) {
    const xs = arrays[spec.px], ys = arrays[spec.py], vs = arrays[spec.pv];
    const [dataLo, dataHi] = finiteRange(vs);
    const lo = spec.value.min === null ? dataLo : spec.value.min;
    let hi = spec.value.max === null ? dataHi : spec.value.max;
    if (!(hi > lo)) hi = lo + 1;
    const colour = (v) => (v === null ? '#999' : viridis((v - lo) / (hi - lo)));
    const [x0, x1] = finiteRange(xs), [y0, y1] = finiteRange(ys);
    const chart = new Chart(canvas, {
      type: 'line',
      data: {
        datasets: [{
          label: spec.value.title,
          data: points(xs, ys),
          borderColor: '#999',
          borderWidth: 3,
          pointRadius: 0,
          pointHoverRadius: 4,
          pointHitRadius: 5,
          pointBackgroundColor: (ctx) => colour(vs[ctx.dataIndex]),
          segment: { borderColor: (ctx) => colour(vs[ctx.p0DataIndex]) },
          spanGaps: false,
        }],
      },
      options: {
        responsive: true,
        maintainAspectRatio: false,
        parsing: false,
        interaction: { mode: 'nearest', intersect: false },
        plugins: {
          legend: { display: false },
          hotlapEqualAxes: { extent: { x0, x1, y0, y1 } },
          tooltip: {
            callbacks: {
              title: () => '',
              label: (item) => spec.value.title + ': ' + fmt(vs[item.dataIndex]) + ' at (' +
                fmt(item.parsed.x) + ', ' + fmt(item.parsed.y) + ')',
            },
          },
        },
        scales: { x: axis(spec.x, false), y: axis(spec.y, false) },
      },
      plugins: [equalAxes],
    });
    colourBar(document.getElementById(spec.id + '-bar'), spec.value.title, lo, hi);
    return chart;
  }

  // Every table sorts by a column when its header is clicked (again: the other way), numbers
  // as numbers ("a/b/c" cells by their first number), other cells as text; empty cells last.
  function sortKey(cell, numeric) {
    const text = cell ? cell.textContent.trim() : '';
    if (!numeric) return text;
    const v = parseFloat(text);
    return isFinite(v) ? v : NaN;
  }
  for (const table of document.querySelectorAll('table')) {
    const body = table.tBodies[0];
    if (!table.tHead || !body) continue;
    table.tHead.querySelectorAll('th').forEach((th, column) => {
      th.classList.add('sortable');
      th.title = 'sort by this column';
      th.addEventListener('click', () => {
        const rows = Array.from(body.rows);
        const numeric = rows.every((r) => !r.cells[column] || r.cells[column].classList.contains('num') ||
          r.cells[column].textContent.trim() === '');
        const up = th.getAttribute('aria-sort') !== 'ascending';
        table.tHead.querySelectorAll('th').forEach((h) => h.removeAttribute('aria-sort'));
        th.setAttribute('aria-sort', up ? 'ascending' : 'descending');
        const keyed = rows.map((r, i) => ({ r, i, k: sortKey(r.cells[column], numeric) }));
        keyed.sort((a, b) => {
          const ea = numeric ? isNaN(a.k) : a.k === '';
          const eb = numeric ? isNaN(b.k) : b.k === '';
          if (ea !== eb) return ea ? 1 : -1;
          const c = numeric ? a.k - b.k : a.k.localeCompare(b.k);
          return (up ? c : -c) || a.i - b.i;
        });
        for (const { r } of keyed) body.appendChild(r);
      });
    });
  }

  report.charts = [];
  for (const spec of data.charts) {
    try {
      const canvas = document.getElementById(spec.id);
      const chart = spec.kind === 'map' ? mapChart(spec, canvas) : lineChart(spec, canvas);
      chart.$spec = spec;
      if (spec.link) {
        chart.$link = spec.link;
        (links[spec.link] = links[spec.link] || []).push(chart);
      }
      report.charts.push(chart);
      const area = chart.chartArea;
      const complete = chart.data.datasets.every((dataset, i) =>
        chart.getDatasetMeta(i).data.length === dataset.data.length);
      if (!area || !(area.width > 0) || !(area.height > 0) || !complete) {
        throw new Error('nothing was drawn');
      }
      report.rendered += 1;
    } catch (error) {
      report.fail(spec.id + ': ' + (error && error.message ? error.message : error));
    }
  }
  report.show();
})();
