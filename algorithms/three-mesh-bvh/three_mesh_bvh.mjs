// tritri process peer: three-mesh-bvh's ExtendedTriangle.intersectsTriangle, called as the
// library calls it inside its BVH queries: two ExtendedTriangles made once and reused, their
// corners set and needsUpdate raised before each test (README.md).
import { ExtendedTriangle } from 'three-mesh-bvh';
import { serve, setThreeTriangles } from '../api/process/tritri_protocol.mjs';

const t1 = new ExtendedTriangle();
const t2 = new ExtendedTriangle();

function overlap(c, o) {
  setThreeTriangles(t1, t2, c, o);
  t1.needsUpdate = true;
  t2.needsUpdate = true;
  return t1.intersectsTriangle(t2);
}

// It handles triangles collapsed to a segment or a point itself (update(): edges shorter than
// 1e-15): it is handed zero-area pairs.
serve(overlap, ['degenerate']);
