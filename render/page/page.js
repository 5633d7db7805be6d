// vibra's lecture page: a video (or PNG frames, or nothing for a figure) and
// the run's time series in uPlot panels that share one zoomable time axis.
// The plots' cursor follows the video; clicking or dragging in a plot seeks.
'use strict';
(() => {
  const page = JSON.parse(document.getElementById('vibra-data').textContent);
  const plots = page.plots;
  const $ = id => document.getElementById(id);

  // ---- The media behind one interface: time in seconds of video. ----------
  const clock = page.clock;  // {fps, frames, interval}: frame k shows simulated time k * interval
  const lastFrame = clock ? clock.frames - 1 : 0;
  const frameAt = s => Math.min(lastFrame, Math.max(0, Math.floor(s * clock.fps + 1e-3)));
  // Seeking to exactly k / fps may show frame k - 1 (Chromium truncates the
  // time to microseconds, just below the frame's timestamp): aim 10 us in.
  const frameTime = k => Math.min(lastFrame, Math.max(0, k)) / clock.fps + 1e-5;
  // Slow motion and pauses: pieces [video, simulated, rate], evaluated as
  // the render evaluates them (scenes/timing/time_map.cpp), so the cursor shows
  // each frame's own simulated time.
  const map = clock && clock.map;
  const mapped = v => {
    let i = 0;
    while (i + 1 < map.length && map[i + 1][0] <= v) i++;
    const end = i + 1 < map.length ? map[i + 1][1] : Infinity;  // the last piece holds T
    return Math.min(end, map[i][1] + (v - map[i][0]) * map[i][2]);
  };
  const mappedFrame = t => {  // the first frame showing simulated time t
    for (let i = 0; i < map.length; i++) {
      const [v, s, r] = map[i], end = i + 1 < map.length ? map[i + 1][1] : Infinity;
      if (t <= end && r > 0) return Math.round((v + Math.max(0, t - s) / r) * clock.fps);
      if (t <= s) return Math.ceil(v * clock.fps - 1e-9);  // a pause: its first frame
    }
    return lastFrame;
  };
  const simulatedTime = s => !clock ? s : map ? mapped(frameAt(s) / clock.fps) : frameAt(s) * clock.interval;
  const mediaTime = t => !clock ? t : frameTime(map ? mappedFrame(t) : Math.round(t / clock.interval));

  function videoMedia(video) {
    return {
      get time() { return video.currentTime; },
      set time(s) { video.currentTime = s; },
      get paused() { return video.paused; },
      play() { video.play().catch(e => console.warn('vibra: the video does not play: ' + e.message)); },
      pause() { video.pause(); },
      set rate(r) { video.playbackRate = r; },
    };
  }

  function framesMedia(img, prefix, digits) {
    const name = k => prefix + String(k).padStart(digits, '0') + '.png';
    const preload = new Image();
    let k = -1, playing = false, rate = 1, startedAt = 0, startFrame = 0;
    const show = i => {
      i = Math.min(lastFrame, Math.max(0, i));
      if (i === k) return;
      k = i;
      img.src = name(k);
      preload.src = name(Math.min(lastFrame, k + 1));
    };
    const restart = () => { startedAt = performance.now(); startFrame = k; };
    const tick = now => {
      if (!playing) return;
      const i = startFrame + Math.floor((now - startedAt) / 1000 * clock.fps * rate);
      if (i > lastFrame) { show(0); restart(); } else show(i);
      requestAnimationFrame(tick);
    };
    show(0);
    return {
      get time() { return k / clock.fps; },
      set time(s) { show(frameAt(s)); restart(); },
      get paused() { return !playing; },
      play() { if (!playing) { playing = true; restart(); requestAnimationFrame(tick); } },
      pause() { playing = false; },
      set rate(r) { rate = r; restart(); },
    };
  }

  function noMedia() {  // a figure: the cursor is a mark the reader places
    let t = plots.t0;
    return { get time() { return t; }, set time(s) { t = s; }, paused: true, play() {}, pause() {}, set rate(r) {} };
  }

  const media = page.media.kind === 'video' ? videoMedia($('video'))
              : page.media.kind === 'frames' ? framesMedia($('frames'), page.media.prefix, page.media.digits)
              : noMedia();

  // ---- A lecture's chapters: each link seeks to its shot. -------------------
  for (const link of document.querySelectorAll('#chapters a'))
    link.onclick = e => { e.preventDefault(); media.time = Number(link.dataset.start) + 1e-5; };

  // ---- Keys and buttons. ----------------------------------------------------
  const step = n => { media.pause(); media.time = frameTime(frameAt(media.time) + n); };
  const toggle = () => (media.paused ? media.play() : media.pause());
  const home = () => { media.time = 0; };
  const end = () => { media.pause(); media.time = frameTime(lastFrame); };
  if (clock) {
    $('play').onclick = toggle;
    $('back').onclick = () => step(-1);
    $('next').onclick = () => step(1);
    $('start').onclick = home;
    $('end').onclick = end;
    $('speed').onchange = e => { media.rate = Number(e.target.value); };
    document.addEventListener('keydown', e => {
      if (e.altKey || e.ctrlKey || e.metaKey || (e.target.tagName === 'SELECT' && e.key !== ' ')) return;
      const action = { ' ': toggle, ArrowRight: () => step(1), ArrowLeft: () => step(-1), Home: home, End: end }[e.key];
      if (!action) return;
      e.preventDefault();
      action();
    });
  }

  // ---- Decoding the decimated series. ---------------------------------------
  // Each series has levels (cells over [t0, t1], two extremes a cell in the
  // order they happened) and maybe every sample ("exact"); values are 16-bit
  // steps of [lo, hi], 65535 for none.
  const decoded = new Map();
  function values(series, part) {
    if (!decoded.has(part)) {
      const bytes = Uint8Array.from(atob(part.data), c => c.charCodeAt(0));
      const view = new DataView(bytes.buffer), n = bytes.length / 2, out = new Float64Array(n);
      const scale = (series.hi - series.lo) / 65534;
      for (let i = 0; i < n; i++) {
        const q = view.getUint16(2 * i, true);
        out[i] = q === 65535 ? NaN : series.lo + q * scale;
      }
      decoded.set(part, out);
    }
    return decoded.get(part);
  }

  // The coarsest resolution that still gives a point per pixel of the view.
  function table(series, a, b, pixels) {
    const options = series.levels.map(level => ({ level, step: (series.t1 - series.t0) / level.cells }));
    if (series.exact) options.push({ exact: series.exact, step: series.exact.dt });
    let choice = options[options.length - 1];
    for (const o of options) if ((b - a) / o.step >= pixels) { choice = o; break; }
    const xs = [], ys = [];
    const push = (x, y) => { xs.push(x); ys.push(Number.isNaN(y) ? null : y); };
    if (choice.exact) {
      const e = choice.exact, v = values(series, e);
      const first = Math.max(0, Math.floor((a - e.t0) / e.dt) - 1), last = Math.min(e.count - 1, Math.ceil((b - e.t0) / e.dt) + 1);
      for (let n = first; n <= last; n++) push(e.t0 + n * e.dt, v[n]);
    } else {
      const level = choice.level, w = choice.step, v = values(series, level);
      const first = Math.max(0, Math.floor((a - series.t0) / w) - 1), last = Math.min(level.cells - 1, Math.ceil((b - series.t0) / w) + 1);
      // Where the curve is monotone over a cell its extremes lie at the
      // cell's ends: drawn there, the line runs straight through them.
      for (let c = first; c <= last; c++) {
        push(series.t0 + (c + 0.02) * w, v[2 * c]);
        push(series.t0 + (c + 0.98) * w, v[2 * c + 1]);
      }
    }
    return [xs, ys];
  }

  // ---- Panels: one uPlot each, one shared view of the time axis. -----------
  let view = [plots.t0, plots.t1];
  const span = plots.t1 - plots.t0;
  const finest = Math.min(...plots.panels.flatMap(p => p.series.map(s =>
    s.exact ? s.exact.dt : (s.t1 - s.t0) / Math.max(1, ...s.levels.map(l => l.cells)))));
  const narrowest = Math.max(span * 1e-9, 8 * finest);
  const hidden = new Set();  // legend keys switched off
  const panelHeight = () => Math.max(140, Math.min(260, Math.round(window.innerHeight * 0.8 / Math.max(1, plots.panels.length))));
  const plotsElement = $('plots');

  // Tick labels with as many decimals as their spacing needs (1.0005, not 1).
  const ticks = (u, splits, axis, space, step) => {
    let decimals = Math.max(0, -Math.floor(Math.log10(step) + 1e-9));
    while (decimals < 12 && splits.some(v => Math.abs(Number(v.toFixed(decimals)) - v) > step * 1e-6)) decimals++;
    return splits.map(v => (Math.abs(v) < step * 1e-6 ? 0 : v).toFixed(decimals));
  };

  const panels = plots.panels.map(panel => {
    const element = document.createElement('div');
    element.className = 'panel';
    plotsElement.append(element);
    const options = {
      title: panel.label,
      width: plotsElement.clientWidth,
      height: panelHeight(),
      legend: { show: false },
      cursor: { drag: { x: false, y: false, setScale: false }, sync: { key: 'vibra' }, points: { show: false } },
      scales: { x: { time: false, auto: false }, y: { auto: false } },
      axes: [{ label: 't', values: ticks }, { size: 84, values: ticks }],
      series: [{ label: 't' }].concat(panel.series.map(s => ({
        label: s.label, stroke: s.color, width: 1.5, dash: s.dash ? [8, 5] : undefined,
        spanGaps: true, points: { show: false }, show: !hidden.has(s.key),
      }))),
    };
    const u = new uPlot(options, [[], ...panel.series.map(() => [])], element);
    const playhead = document.createElement('div');
    playhead.className = 'playhead';
    u.over.append(playhead);
    return { panel, u, playhead };
  });

  function yRange(data) {
    let lo = Infinity, hi = -Infinity;
    for (let i = 1; i < data.length; i++) {
      for (const y of data[i]) if (y != null) { if (y < lo) lo = y; if (y > hi) hi = y; }
    }
    if (lo > hi) return [-1, 1];
    const pad = hi > lo ? 0.06 * (hi - lo) : Math.max(1e-9, Math.abs(hi) * 0.1 || 1);
    return [lo - pad, hi + pad];
  }

  function redraw() {
    const [a, b] = view;
    for (const { panel, u } of panels) {
      const pixels = Math.max(100, u.bbox.width / devicePixelRatio);
      const tables = panel.series.map(s => table(s, a, b, pixels));
      const data = tables.length === 1 ? tables[0] : uPlot.join(tables);
      u.batch(() => {
        u.setData(data, false);
        u.setScale('x', { min: a, max: b });
        const shown = [data[0]].concat(data.slice(1).filter((_, i) => !hidden.has(panel.series[i].key)));
        const [lo, hi] = yRange(shown.length > 1 ? shown : data);
        u.setScale('y', { min: lo, max: hi });
      });
    }
    lastCursor = NaN;
  }

  function setView(a, b) {
    let w = Math.min(span, Math.max(narrowest, b - a));
    a = Math.min(Math.max(a, plots.t0), plots.t1 - w);
    view = [a, a + w];
    redraw();
  }

  // ---- Legend: one entry a key (a run, or "exact"), shown with two or more.
  const keys = [];
  for (const p of plots.panels) for (const s of p.series) if (!keys.some(k => k.key === s.key)) keys.push(s);
  if (keys.length > 1) {
    for (const s of keys) {
      const label = document.createElement('label');
      label.dataset.key = s.key;
      label.innerHTML = '<span class="swatch"></span>';
      label.firstChild.style.borderTopColor = s.color;
      if (s.dash) label.firstChild.style.borderTopStyle = 'dashed';
      label.append(s.key);
      label.title = 'Show or hide ' + s.key;
      label.onclick = () => {
        hidden.has(s.key) ? hidden.delete(s.key) : hidden.add(s.key);
        label.classList.toggle('off', hidden.has(s.key));
        for (const { panel, u } of panels)
          panel.series.forEach((series, i) => { if (series.key === s.key) u.setSeries(i + 1, { show: !hidden.has(s.key) }); });
        redraw();
      };
      $('legend').append(label);
    }
  }

  // ---- Mouse: click or drag seeks; wheel zooms; Shift+drag or a drag on the
  // time axis pans; double-click shows the whole run again. -----------------
  for (const { u } of panels) {
    const timeAt = e => u.posToVal(e.clientX - u.over.getBoundingClientRect().left, 'x');
    const seek = e => { media.time = mediaTime(Math.min(plots.t1, Math.max(plots.t0, timeAt(e)))); drawCursor(true); };
    const pan = start => {
      const [a, b] = view, perPixel = (b - a) / u.over.clientWidth;
      return e => setView(a - (e.clientX - start.clientX) * perPixel, b - (e.clientX - start.clientX) * perPixel);
    };
    const drag = (start, move) => {
      const up = () => { window.removeEventListener('mousemove', move); window.removeEventListener('mouseup', up); };
      window.addEventListener('mousemove', move);
      window.addEventListener('mouseup', up);
    };
    u.over.addEventListener('mousedown', e => {
      if (e.button !== 0) return;
      e.preventDefault();
      if (e.shiftKey) return drag(e, pan(e));
      seek(e);
      drag(e, seek);
    });
    const axis = u.root.querySelector('.u-axis');
    axis.style.cursor = 'ew-resize';
    axis.addEventListener('mousedown', e => { if (e.button === 0) { e.preventDefault(); drag(e, pan(e)); } });
    u.over.addEventListener('wheel', e => {
      e.preventDefault();
      const [a, b] = view, unit = e.deltaMode === 1 ? 16 : e.deltaMode === 2 ? 400 : 1;
      if (e.shiftKey || Math.abs(e.deltaX) > Math.abs(e.deltaY)) {
        const d = (e.shiftKey ? e.deltaY : e.deltaX) * unit * (b - a) / u.over.clientWidth;
        return setView(a + d, b + d);
      }
      const f = Math.exp(e.deltaY * unit * 0.002), t = timeAt(e);
      setView(t - (t - a) * f, t + (b - t) * f);
    }, { passive: false });
    u.over.addEventListener('dblclick', () => setView(plots.t0, plots.t1));
  }

  // ---- The cursor follows the media, every animation frame. ----------------
  let lastCursor = NaN, lastPaused = null;
  function drawCursor(force) {
    const t = simulatedTime(media.time);
    if (clock && media.paused !== lastPaused) {
      lastPaused = media.paused;
      $('play').innerHTML = media.paused ? '&#9654; Play' : '&#10074;&#10074; Pause';
    }
    if (t === lastCursor && !force) return;
    lastCursor = t;
    const [a, b] = view;
    if (!media.paused && (t > b || t < a) && b - a < span) setView(t, t + (b - a));  // keep it in sight
    for (const { u, playhead } of panels) {
      const x = u.valToPos(t, 'x');
      playhead.style.display = t < view[0] || t > view[1] ? 'none' : '';
      playhead.style.transform = 'translateX(' + x + 'px)';
    }
    if (clock)
      $('readout').textContent = 't = ' + t.toFixed(3) + '   frame ' + (frameAt(media.time) + 1) + ' of ' + clock.frames;
  }
  const animate = () => { drawCursor(false); requestAnimationFrame(animate); };

  let resizeTimer = 0;
  window.addEventListener('resize', () => {
    clearTimeout(resizeTimer);
    resizeTimer = setTimeout(() => {
      for (const { u } of panels) u.setSize({ width: plotsElement.clientWidth, height: panelHeight() });
      redraw();
    }, 100);
  });

  redraw();
  animate();
  // For tests and the curious: the page's state.
  window.vibraPage = { media, panels, get view() { return view; }, setView, simulatedTime, mediaTime };
})();
