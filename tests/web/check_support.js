// What the browser build's node tests share: their two arguments resolved, and one line per check with the verdict at exit.
'use strict';
const path = require('path');

const failures = [];
function check(ok, what) {
  console.log((ok ? 'ok    ' : 'FAIL  ') + what);
  if (!ok) failures.push(what);
}

/// Says how the checks went and exits 1 when one failed.
function finish() {
  console.log(failures.length ? `${failures.length} checks failed` : 'every check held');
  process.exit(failures.length ? 1 : 0);
}

// Usage of every test here: node TEST.js BUILD/web/vibra_core.js BUILD/vibra
const [coreJs, vibra] = process.argv.slice(2).map(p => path.resolve(p));
module.exports = { check, finish, coreJs, vibra };
