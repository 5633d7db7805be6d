// web/canvas/replay.js against a recording 2D context: each operation of web/canvas/draw_commands.hpp becomes the canvas calls it stands for.
'use strict';
const fs = require('fs');
const path = require('path');
const { check, finish } = require('./check_support.js');
const root = path.resolve(__dirname, '..', '..');
const { replayCommands, kOperationCount } = require(path.join(root, 'web/canvas/replay.js'));

// A 2D context that writes down every call and property set, in order.
function recordingContext() {
  const calls = [];
  const canvas = { width: 40, height: 30 };
  const target = { canvas };
  const ctx = new Proxy(target, {
    get: (t, name) => (name in t ? t[name] : (...args) => calls.push(`${String(name)}(${args.join(',')})`)),
    set: (t, name, value) => (calls.push(`${String(name)}=${Array.isArray(value) ? '[' + value + ']' : value}`), true),
  });
  return { ctx, calls };
}

// Every operation of the C++ enum has a replayer, in the same order.
const header = fs.readFileSync(path.join(root, 'web/canvas/draw_commands.hpp'), 'utf8');
const enumBody = /enum class Op : int \{([\s\S]*?)\};/.exec(header)[1];
const names = enumBody.match(/\bk[A-Z]\w*/g);
check(names.length === kOperationCount, `replay.js knows all ${names.length} operations of draw_commands.hpp`);

// The operations of "a filled rectangle and a dashed line" (tests/web/backend/cairo_shim_test.cpp).
const numbers = [3, 10, 20, 4, 40, 20, 5, 6, 1, 0, 0, 0.5, 0, 2,
                 3, 5, 7, 4, 15, 7, 7, 0, 0, 1, 1, 3, 0, 1, 1, 0, 0, 1, 5, 7, 2, 1, 4, 2,
                 10, 0, 1, 0, 0, 1, 2, 0, 0, 1, 0, 0, 1, 3, 4, 2, 1, 0, 1];
const { ctx, calls } = recordingContext();
replayCommands(ctx, numbers, "italic 20px 'DejaVu Sans'\nmg");
const expected = [
  'setTransform(1,0,0,1,0,0)', 'moveTo(10,20)', 'lineTo(40,20)', 'closePath()', 'fillStyle=rgba(255,0,0,0.5)',
  'fill(nonzero)', 'beginPath()', 'moveTo(5,7)', 'lineTo(15,7)', 'strokeStyle=rgba(0,0,255,1)', 'lineWidth=3',
  'lineJoin=miter', 'lineCap=round', 'setTransform(1,0,0,1,5,7)', 'setLineDash(4,2)', 'lineDashOffset=1',
  'stroke()', 'setTransform(1,0,0,1,0,0)', 'setLineDash()', 'fillStyle=rgba(255,0,0,1)', 'lineWidth=2',
  'lineJoin=miter', 'lineCap=butt', 'setTransform(1,0,0,1,3,4)', "font=italic 20px 'DejaVu Sans'",
  'textBaseline=alphabetic', 'fillText(mg,2,1)', 'setTransform(1,0,0,1,0,0)'];
check(JSON.stringify(calls) === JSON.stringify(expected), 'paths, fills, dashed strokes and text runs replay as canvas calls');
if (JSON.stringify(calls) !== JSON.stringify(expected)) console.log(calls);

// A fill with a tile (the bumpy road's hatched ground): the tile drawn on its own canvas by its own
// operations and strings, then the path filled with it as a repeated pattern, placed, pixels not smoothed.
// The numbers of "a fill with a surface pattern" (tests/web/backend/cairo_shim_test.cpp), with a text run in the tile.
const tileCalls = [];
const outerCalls = [];
let placed = null;
// A context that writes down its calls, makes tiles that write theirs down too, and patterns that keep their placing.
function tilingContext(calls, width, height) {
  const target = {
    canvas: { width, height },
    makeCanvas: (w, h) => {
      tileCalls.push(`canvas(${w},${h})`);
      const tile = tilingContext(tileCalls, w, h);
      return tile.canvas;
    },
    createPattern: (canvas, repetition) => (calls.push(`createPattern(${canvas.width}x${canvas.height},${repetition})`),
                                            { setTransform: m => { placed = m; } }),
  };
  const ctx = new Proxy(target, {
    get: (t, name) => (name in t ? t[name] : (...args) => calls.push(`${String(name)}(${args.join(',')})`)),
    set: (t, name, value) => (calls.push(`${String(name)}=${typeof value === 'object' ? 'pattern' : value}`), true),
  });
  target.canvas.getContext = () => ctx;
  return ctx;
}
const textRun = [10, 0, 0, 0, 0, 1, 2, 0, 0, 1, 0, 0, 1, 0, 0, 3, 0, 0, 1];
replayCommands(tilingContext(outerCalls, 40, 20), [3, 15, 5, 4, 17, 5, 4, 17, 7, 5, 14, 4, 4, 1, 0, 1, 0, 0, 1, 7, 0, 0, 5 + textRun.length, 1, 2,
                           9, 0, 0, 1, 1, ...textRun], "unused\n12px 'DejaVu Sans'\nx");
check(JSON.stringify(tileCalls) === JSON.stringify(['canvas(4,4)', 'fillStyle=rgba(0,0,255,1)', 'fillRect(0,0,4,4)',
        'fillStyle=rgba(0,0,0,1)', 'lineWidth=2', 'lineJoin=miter', 'lineCap=butt', 'setTransform(1,0,0,1,0,0)',
        "font=12px 'DejaVu Sans'", 'textBaseline=alphabetic', 'fillText(x,3,0)', 'setTransform(1,0,0,1,0,0)']),
      "a tile is drawn on its own canvas by its own operations, with its own strings");
check(outerCalls.slice(-5).join(' ') === 'createPattern(4x4,repeat) imageSmoothingEnabled=false fillStyle=pattern '
      + 'fill(nonzero) imageSmoothingEnabled=true' && JSON.stringify(placed) === '{"a":1,"b":0,"c":0,"d":1,"e":7,"f":0}',
      'the path is filled with the tile repeated, placed by its matrix, pixels not smoothed');
if (tileCalls.length !== 12) console.log(tileCalls, outerCalls);

let refused = '';
try { replayCommands(ctx, [99], ''); } catch (e) { refused = e.message; }
check(refused === 'drawing operation 99 at 0 is unknown', 'an unknown operation is refused, naming it');
finish();
