// Holds the WebAssembly core (web/core_api.cpp) against the native solver: the same rows to 1e-12, the same refusals.
// Usage: node core_matches_native.js BUILD/web/vibra_core.js BUILD/vibra
'use strict';
const { execFileSync, spawnSync } = require('child_process');
const fs = require('fs');
const os = require('os');
const path = require('path');
const { check, finish, coreJs, vibra } = require('./check_support.js');

// Models, schemes and kinds of key (angle, formula, choice, adaptive steps, events, 2-D state), with
// the largest relative difference allowed: 1e-12 for a fixed step. An adaptive scheme chooses its
// steps from error estimates, where the browser's sin() (musl's) may differ from glibc's in the last
// bit and shift a step: held to 1e-9, a thousandth of its rtol.
const runs = [
  ['pendulum', ['Theta=60', 'alpha=0.4', 'scheme=rk4', 'dt=0.05', 'T=30']],
  ['pendulum', ['Theta=120', 'alpha=0', 'scheme=euler_cromer', 'dt=0.01', 'periods=3']],
  ['undamped', ['scheme=centered', 'dt=0.1', 'periods=5']],
  ['vibration', ['b=0.3', 'damping=quadratic', 'F=sin(1.2*t)', 'scheme=rk2', 'dt=0.02', 'T=20']],
  ['vibration', ['s=sin(u)', 'scheme=rk4', 'dt=0.1', 'T=10']],
  ['vibration', ['s=sin(u)', 'scheme=dopri5', 'T=10'], 1e-9],
  ['bumpy_road', ['road=sine', 'scheme=euler_cromer']],
  ['elastic_pendulum', ['scheme=velocity_verlet']],
  ['bouncing_ball', ['T=3']],
  ['rlc', ['scheme=crank_nicolson']],
];

// Settings the CLI refuses with exit code 2 and one line, which the page must show as they are.
const refusals = [
  ['pendulum', ['dt=abc']],
  ['pendulum', ['Thta=3']],
  ['pendulum', ['scheme=rk5']],
  ['vibration', ['F=sin(x)']],
  ['pendulum', ['dt=-1']],
  ['pendel', []],
];

// Road files, written for both: here into a scratch folder the native runs work in, and into the
// browser build's own file system, so that `road=NAME` names the same heights in both.
const roads = { 'road.txt': '0\n0.01\n-0.02\n0.015\n0\n'.repeat(200), 'bad_road.txt': '0\n0.01\n1e-2x\n0\n' };
const scratch = fs.mkdtempSync(path.join(os.tmpdir(), 'vibra-web-'));
process.on('exit', () => fs.rmSync(scratch, { recursive: true, force: true }));
for (const [name, text] of Object.entries(roads)) fs.writeFileSync(path.join(scratch, name), text);
runs.push(['bumpy_road', ['road=road.txt', 'dx=0.05', 'T=4', 'scheme=rk4']]);
refusals.push(['bumpy_road', ['road=bad_road.txt', 'dx=0.05']]);

function nativeRows(model, settings) {
  const args = ['solve', model, ...settings.flatMap(s => ['--set', s])];
  const lines = execFileSync(vibra, args, { encoding: 'utf8', maxBuffer: 1 << 28, cwd: scratch }).trim().split('\n');
  return { columns: lines[0], rows: lines.slice(1).map(l => l.split(',').map(Number)) };
}

function webRun(core, model, settings) {
  const code = core.ccall('vibra_solve', 'number', ['string', 'string'], [model, settings.join('\n')]);
  const error = core.ccall('vibra_error', 'string', [], []);
  const columns = core.ccall('vibra_columns', 'string', [], []);
  const n = core.ccall('vibra_row_count', 'number', [], []);
  const width = columns ? columns.split(',').length : 0;
  const at = core.ccall('vibra_rows', 'number', [], []) / 8;
  const flat = core.HEAPF64.subarray(at, at + n * width);
  const rows = [];
  for (let i = 0; i < n; i++) rows.push(Array.from(flat.subarray(i * width, (i + 1) * width)));
  return { code, error, columns, rows };
}

function largestDifference(a, b) {
  let worst = 0;
  for (let i = 0; i < a.length; i++)
    for (let j = 0; j < a[i].length; j++) {
      const scale = Math.max(1, Math.abs(b[i][j]));
      if (!(Math.abs(a[i][j] - b[i][j]) / scale <= worst)) worst = Math.abs(a[i][j] - b[i][j]) / scale;
    }
  return worst;
}

function compareRun(core, [model, settings, tolerance = 1e-12]) {
  const what = `${model} ${settings.join(' ')}`;
  let native;
  try {
    native = nativeRows(model, settings);
  } catch (e) {
    return check(false, `${what}: the native solver refused the run: ${String(e.stderr || e).trim()}`);
  }
  const web = webRun(core, model, settings);
  check(web.code === 0 && web.error === '', `${what}: solved in the browser build (${web.error || 'no error'})`);
  check(web.columns === native.columns, `${what}: columns ${web.columns} as native ${native.columns}`);
  check(web.rows.length === native.rows.length && native.rows.length > 10,
        `${what}: ${web.rows.length} rows as native ${native.rows.length}`);
  if (web.rows.length !== native.rows.length) return;
  const worst = largestDifference(web.rows, native.rows);
  check(worst <= tolerance, `${what}: largest relative difference ${worst.toExponential(2)} <= ${tolerance}`);
}

function compareRefusal(core, [model, settings]) {
  const what = `${model} ${settings.join(' ')}`;
  const args = ['solve', model, ...settings.flatMap(s => ['--set', s])];
  const native = spawnSync(vibra, args, { encoding: 'utf8', cwd: scratch });
  const web = webRun(core, model, settings);
  check(native.status === 2 && web.code === 2, `${what}: refused with code 2 (native ${native.status}, web ${web.code})`);
  check(native.stderr === `vibra: error: ${web.error}\n`, `${what}: the CLI's reason: ${web.error}`);
  check(web.rows.length === 0 && web.columns === '', `${what}: no rows kept from a refused run`);
}

require(coreJs)().then(core => {
  for (const [name, text] of Object.entries(roads)) core.FS.writeFile(name, text);
  runs.forEach(run => compareRun(core, run));
  refusals.forEach(refusal => compareRefusal(core, refusal));
  compareRun(core, runs[0]);  // a refusal leaves nothing behind that changes the next run
  finish();
});
