// The process protocol (harness/run/process_plugin.hpp) for a triangle test in JavaScript:
// serve() reads cases from standard input and answers them, greets when tritri speaks protocol
// 2, and times the test over a pool on request ('#time'), on this runtime's monotonic clock
// (process.hrtime.bigint), so that a test is timed where its users run it.
//
// A test is a function (coords, offset) -> boolean: coords is a Float64Array holding the pair's
// 18 coordinates (ax ay az bx by bz cx cy cz px py pz qx qy qz rx ry rz) from `offset` on.

const protocol = Number(process.env.TRITRI_PROTOCOL || 1);

// For a test on three.js triangles (Triangle and its subclasses): sets t1's and t2's corners
// from the pair's coordinates at offset.
export function setThreeTriangles(t1, t2, c, o) {
  for (const [t, k] of [[t1, o], [t2, o + 9]]) {
    t.a.set(c[k], c[k + 1], c[k + 2]);
    t.b.set(c[k + 3], c[k + 4], c[k + 5]);
    t.c.set(c[k + 6], c[k + 7], c[k + 8]);
  }
}

function answerWord(overlap) {
  return overlap === true ? '1' : overlap === false ? '0' : 'unsupported';
}

// Reads the 18 numbers of a case line into coords at offset; returns its name.
function readCase(line, coords, offset) {
  const words = line.trim().split(/\s+/);
  if (words.length < 19) throw new Error(`a case line has ${words.length - 1} numbers, not 18: '${line}'`);
  for (let k = 0; k < 18; k++) coords[offset + k] = Number(words[k + 1]);
  return words[0];
}

// Whole passes over the pool until minNs have passed; ns per pair. The sum of the answers is
// kept live, so that no pass can be left out by the compiler.
let live = 0;
function passes(test, n, coords, minNs) {
  let count = 0;
  const start = process.hrtime.bigint();
  let elapsed = 0n;
  do {
    for (let i = 0; i < n; i++) live += test(coords, 18 * i) ? 1 : 0;
    count++;
    elapsed = process.hrtime.bigint() - start;
  } while (elapsed < minNs);
  return Number(elapsed) / (count * n);
}

// The pool's answers (its first pass), the warm-up (passes for minSeconds, untimed: the JIT
// compiles the test meanwhile), then each repetition's ns per pair.
function timePool(test, names, coords, repetitions, minSeconds) {
  const n = names.length;
  const answers = new Array(n);
  for (let i = 0; i < n; i++) answers[i] = test(coords, 18 * i);
  const minNs = BigInt(Math.round(minSeconds * 1e9));
  passes(test, n, coords, minNs);
  const times = [];
  for (let r = 0; r < repetitions; r++) times.push(passes(test, n, coords, minNs));
  if (live < 0) process.stderr.write('impossible\n');
  const lines = names.map((name, i) => `${name} ${answerWord(answers[i])}`);
  lines.push('#timed ' + times.map((t) => t.toPrecision(6)).join(' '));
  return lines.join('\n') + '\n';
}

// features: the words of the greeting (e.g. ['degenerate']); 'timing' is always offered.
export function serve(test, features = []) {
  if (protocol >= 2) process.stdout.write(['#tritri 2', ...features, 'timing'].join(' ') + '\n');
  const one = new Float64Array(18);
  let pending = '';
  let pool = null;  // while a '#time' request's cases are read
  process.stdin.setEncoding('latin1');
  process.stdin.on('data', (chunk) => {
    const lines = (pending + chunk).split('\n');
    pending = lines.pop();
    let out = '';
    for (const line of lines) {
      if (pool) {
        pool.names.push(readCase(line, pool.coords, 18 * pool.names.length));
        if (pool.names.length === pool.n) {
          out += timePool(test, pool.names, pool.coords, pool.repetitions, pool.minSeconds);
          pool = null;
        }
      } else if (line.startsWith('#time ')) {
        const [, n, repetitions, minSeconds] = line.trim().split(/\s+/).map(Number);
        pool = { n, repetitions, minSeconds, names: [], coords: new Float64Array(18 * n) };
      } else if (line.trim() !== '' && !line.startsWith('#')) {
        const name = readCase(line, one, 0);
        out += `${name} ${answerWord(test(one, 0))}\n`;
      }
    }
    // Everything read so far is answered: flushed now, as the protocol asks.
    if (out) process.stdout.write(out);
  });
}
