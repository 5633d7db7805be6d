// The browser spike's page script: re-solve latency of the WebAssembly core, and two ways to draw the free-body diagram at 960x540.
// Option A hands each path of the native still (its SVG: the scene code's own geometry, fills,
// strokes and glyph outlines) to the browser's 2D canvas as Path2D; option B's floor is what any
// software rasterizer pays before drawing anything: a frame of pixels from wasm memory put on the canvas.
'use strict';

// Style declarations of one element ("fill:rgb(10%,10%,12%);stroke-width:2") as an object.
function styleOf(element, inherited) {
  const style = Object.assign({}, inherited);
  for (const part of (element.getAttribute('style') || '').split(';')) {
    const [key, value] = part.split(':').map(s => s && s.trim());
    if (key && value) style[key] = value;
  }
  return style;
}

// The still's SVG as a flat list of drawing operations: path, style, transform and clip.
function operationsOf(svgText) {
  const svg = new DOMParser().parseFromString(svgText, 'image/svg+xml').documentElement;
  const byId = {};
  svg.querySelectorAll('[id]').forEach(e => (byId[e.id] = e));
  const clipOf = id => new Path2D(byId[id].querySelector('path').getAttribute('d'));
  const operations = [];
  function walk(element, style, clips) {
    for (const child of element.children) {
      const name = child.tagName;
      if (name === 'defs' || name === 'clipPath') continue;
      const own = styleOf(child, style);
      const clip = /url\(#(.*)\)/.exec(child.getAttribute('clip-path') || '');
      const inner = clip ? clips.concat([clipOf(clip[1])]) : clips;
      if (name === 'g') walk(child, own, inner);
      else if (name === 'path') operations.push({ path: new Path2D(child.getAttribute('d')), style: own, clips: inner, x: 0, y: 0 });
      else if (name === 'rect') {
        const p = new Path2D();
        p.rect(+child.getAttribute('x'), +child.getAttribute('y'), +child.getAttribute('width'), +child.getAttribute('height'));
        operations.push({ path: p, style: own, clips: inner, x: 0, y: 0 });
      } else if (name === 'use') {
        const glyph = byId[child.getAttribute('xlink:href').slice(1)].querySelector('path');
        operations.push({ path: new Path2D(glyph.getAttribute('d')), style: styleOf(glyph, own), clips: inner,
                          x: +child.getAttribute('x'), y: +child.getAttribute('y') });
      }
    }
  }
  walk(svg, { fill: 'rgb(0%,0%,0%)' }, []);
  return operations;
}

function drawOperations(ctx, operations) {
  for (const op of operations) {
    const s = op.style;
    ctx.save();
    for (const clip of op.clips) ctx.clip(clip);
    ctx.translate(op.x, op.y);
    if (s.fill && s.fill !== 'none') {
      ctx.fillStyle = s.fill;
      ctx.globalAlpha = +(s['fill-opacity'] || 1);
      ctx.fill(op.path, s['fill-rule'] === 'evenodd' ? 'evenodd' : 'nonzero');
    }
    if (s.stroke && s.stroke !== 'none') {
      ctx.strokeStyle = s.stroke;
      ctx.globalAlpha = +(s['stroke-opacity'] || 1);
      ctx.lineWidth = +(s['stroke-width'] || 1);
      ctx.lineCap = s['stroke-linecap'] || 'butt';
      ctx.lineJoin = s['stroke-linejoin'] || 'miter';
      ctx.stroke(op.path);
    }
    ctx.restore();
  }
}

const median = xs => xs.slice().sort((a, b) => a - b)[Math.floor(xs.length / 2)];

// Milliseconds per call of `work`, the median of `runs`; each run ends with a pixel read so that the
// canvas has really drawn (its commands are otherwise deferred).
function timeFrames(ctx, runs, work) {
  const times = [];
  for (let i = 0; i < runs; i++) {
    const start = performance.now();
    work(i);
    ctx.getImageData(0, 0, 1, 1);
    times.push(performance.now() - start);
  }
  return median(times);
}

// Frames per second of requestAnimationFrame drawing `work` for `seconds`.
function animationRate(work, seconds) {
  return new Promise(resolve => {
    let frames = 0;
    const start = performance.now();
    function frame(now) {
      work(frames++);
      if (now - start < seconds * 1000) requestAnimationFrame(frame);
      else resolve(frames / ((now - start) / 1000));
    }
    requestAnimationFrame(frame);
  });
}

function resolveLatency(core, settings, runs) {
  const times = [];
  let rows = 0;
  for (let i = 0; i < runs; i++) {
    const start = performance.now();
    if (core.ccall('vibra_solve', 'number', ['string', 'string'], ['pendulum', settings]) !== 0)
      throw new Error(core.ccall('vibra_error', 'string', [], []));
    times.push(performance.now() - start);
    rows = core.ccall('vibra_row_count', 'number', [], []);
  }
  return { ms: median(times), rows };
}

async function measureSpike(svgText) {
  const canvas = document.getElementById('frame');
  const ctx = canvas.getContext('2d');
  const core = await createVibraCore();
  const figures = {};
  figures.resolve_default = resolveLatency(core, 'Theta=60\nalpha=0.4\nperiods=10', 21);
  figures.resolve_fine = resolveLatency(core, 'Theta=60\nalpha=0.4\nperiods=10\nsteps_per_period=2000', 5);
  const operations = operationsOf(svgText);
  figures.operations = operations.length;
  const drawA = () => { ctx.clearRect(0, 0, 960, 540); drawOperations(ctx, operations); };
  figures.a_ms = timeFrames(ctx, 60, drawA);
  figures.a_fps = await animationRate(drawA, 2);
  const pixels = core._malloc(960 * 540 * 4);
  const drawB = i => {
    const frame = new Uint8ClampedArray(core.HEAPU8.buffer, pixels, 960 * 540 * 4);
    frame.fill(i & 255);  // stands in for the rasterizer's output
    ctx.putImageData(new ImageData(frame, 960, 540), 0, 0);
  };
  figures.b_floor_ms = timeFrames(ctx, 60, drawB);
  figures.b_floor_fps = await animationRate(drawB, 2);
  core._free(pixels);
  drawA();
  return figures;
}
