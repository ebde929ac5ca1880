// tritri process peer: Rapier (parry compiled to WebAssembly, @dimforge/rapier3d-compat):
// Shape.intersectsShape on two Triangle shapes at the identity pose, as a user tests two
// triangles with it (README.md). The coordinates become float32 on their way into WebAssembly.
import RAPIER from '@dimforge/rapier3d-compat';
import { serve } from '../api/process/tritri_protocol.mjs';

await RAPIER.init();

const origin = { x: 0, y: 0, z: 0 };
const identity = { x: 0, y: 0, z: 0, w: 1 };

function overlap(c, o) {
  const t1 = new RAPIER.Triangle({ x: c[o], y: c[o + 1], z: c[o + 2] }, { x: c[o + 3], y: c[o + 4], z: c[o + 5] },
                                 { x: c[o + 6], y: c[o + 7], z: c[o + 8] });
  const t2 = new RAPIER.Triangle({ x: c[o + 9], y: c[o + 10], z: c[o + 11] }, { x: c[o + 12], y: c[o + 13], z: c[o + 14] },
                                 { x: c[o + 15], y: c[o + 16], z: c[o + 17] });
  return t1.intersectsShape(origin, identity, t2, origin, identity);
}

serve(overlap);
