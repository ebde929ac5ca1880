// tritri process peer: fast-triangle-triangle-intersection's trianglesIntersect(t1, t2), on two
// three.js Triangles, as its README calls it; intersecting when it returns Intersection.Cross or
// Intersection.Coplanar, not when it returns null (README.md).
import { Triangle } from 'three';
// The package's ES module build, as bundlers take it (its "module" field); node's "main" is a
// UMD build that node cannot load as the module the package declares itself.
import { trianglesIntersect } from 'fast-triangle-triangle-intersection/build/index.esm.js';
import { serve, setThreeTriangles } from '../api/process/tritri_protocol.mjs';

const t1 = new Triangle();
const t2 = new Triangle();

// It warns on the console for every pair it finds degenerate; counted here, and said once at
// exit, so that a corpus run's standard error stays readable.
let warnings = 0;
console.warn = () => { warnings++; };
process.on('exit', () => {
  if (warnings) process.stderr.write(`fast-tri-tri: the library warned ${warnings} times (degenerate triangles)\n`);
});

function overlap(c, o) {
  setThreeTriangles(t1, t2, c, o);
  return trianglesIntersect(t1, t2) !== null;
}

// Zero-area triangles are not passed: it refuses them itself (null, "Degenerated triangles
// provided, skipping"), which is no answer about them.
serve(overlap);
