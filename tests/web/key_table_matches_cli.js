// Holds the page's key table (web/key_table.cpp) to the CLI: every model's keys as `vibra solve MODEL --help` lists them, ranges as refused.
// Usage: node key_table_matches_cli.js BUILD/web/vibra_core.js BUILD/vibra
'use strict';
const { spawnSync } = require('child_process');
const { check, finish, coreJs, vibra } = require('./check_support.js');

function modelNames() {
  const refused = spawnSync(vibra, ['solve', 'no-such-model'], { encoding: 'utf8' }).stderr;
  return /choose one of (.*)$/m.exec(refused)[1].split(', ');
}

// The help's key lines: "  NAME  MEANING (a|b)  unit: UNIT  default: DEFAULT", "-" for none.
function helpKeys(model) {
  const help = spawnSync(vibra, ['solve', model, '--help'], { encoding: 'utf8' }).stdout;
  return help.split('\n').map(l => /^  (\S+)\s+(.*?)\s+unit: (.*?)\s+default: (.*)$/.exec(l)).filter(Boolean)
    .map(([, name, meaning, unit, value]) => ({ name, meaning, unit: unit === '-' ? '' : unit, default: value === '-' ? '' : value }));
}

function checkModel(core, model) {
  const table = JSON.parse(core.ccall('vibra_model_keys', 'string', ['string'], [model]));
  const help = helpKeys(model);
  check(table.map(k => k.name).join(' ') === help.map(k => k.name).join(' ') && help.length > 3,
        `${model}: keys ${table.map(k => k.name).join(' ')} as the help lists them`);
  help.forEach((h, i) => {
    const k = table[i] || {};
    const shown = k.meaning + (k.choices && k.choices.length && k.name !== 'scheme' ? ` (${k.choices.join('|')})` : '');
    check(shown === h.meaning && k.unit === h.unit && k.default === h.default,
          `${model} ${h.name}: meaning, unit '${h.unit}' and default '${h.default}' as the help says`);
  });
  return table;
}

// A value just outside a key's range is refused by the solver, naming the key: the range is the one enforced.
function checkRangeEdges(core, model, key) {
  const r = key.range;
  const outside = [r.hi * 10];
  if (r.lo_excluded) outside.push(r.lo);
  else outside.push(r.lo - Math.abs(r.lo) - 1);
  for (const value of outside) {
    const code = core.ccall('vibra_solve', 'number', ['string', 'string'], [model, `${key.name}=${value}`]);
    const error = core.ccall('vibra_error', 'string', [], []);
    check(code === 2 && error.startsWith(`${key.name}=`) && error.includes(' must be '),
          `${model} ${key.name}=${value} is outside its range: ${error}`);
  }
}

// Rows of the CLI's table of ranges, known here: what the page's controls must offer.
const knownRanges = {
  dt: { lo: 0, hi: 1e9, lo_excluded: true, whole: false, inf_allowed: false },
  T: { lo: 0, hi: 1e15, lo_excluded: true, whole: false, inf_allowed: true },
  Theta: { lo: -1e12, hi: 1e12, lo_excluded: false, whole: false, inf_allowed: false },
};

require(coreJs)().then(core => {
  const models = modelNames();
  check(models.length >= 11, `the CLI names ${models.length} models`);
  for (const model of models) {
    const table = checkModel(core, model);
    table.filter(k => k.range).forEach(k => checkRangeEdges(core, model, k));
    check(table.filter(k => k.range).length > 0 && table.every(k => !!k.range === ['number', 'angle'].includes(k.control)),
          `${model}: a range for each number and angle key, none for the others`);
  }
  const pendulum = JSON.parse(core.ccall('vibra_model_keys', 'string', ['string'], ['pendulum']));
  for (const [name, range] of Object.entries(knownRanges)) {
    const key = pendulum.find(k => k.name === name) || {};
    check(JSON.stringify(key.range) === JSON.stringify(range), `pendulum ${name}: range ${JSON.stringify(key.range)}`);
  }
  check(core.ccall('vibra_model_keys', 'string', ['string'], ['pendel']) === '', 'an unknown model has no key table');
  finish();
});
