// npm fast-2d-poisson-disk-sampling 1.0.3 (K. Chapelier): fill() on the unit
// square (shape [1, 1]; a box: it has no tiling), Math.random. Times only
// fill() (the constructor allocates the grid; both timed, reported apart).
// Usage: node fast2d.js RADIUS [TRIES=30] [OUT.csv]   (NODE_PATH: its node_modules)
const FastPoissonDiskSampling = require('fast-2d-poisson-disk-sampling');
const fs = require('fs');
const r = parseFloat(process.argv[2]);
const tries = process.argv.length > 3 ? parseInt(process.argv[3]) : 30;
const c0 = process.cpuUsage(), w0 = process.hrtime.bigint();
const p = new FastPoissonDiskSampling({shape: [1, 1], radius: r, tries: tries});
const pts = p.fill();
const c1 = process.cpuUsage(c0), w1 = process.hrtime.bigint();
const cpu = (c1.user + c1.system) * 1e-6, wall = Number(w1 - w0) * 1e-9;
console.log(`RESULT fast-2d-poisson-disk-sampling dim=2 samples=${pts.length} cpu_s=${cpu.toFixed(6)} wall_s=${wall.toFixed(6)} Msamples_per_cpu_s=${(pts.length / cpu * 1e-6).toFixed(4)}`);
if (process.argv.length > 4) {
  const lines = ['x,y'];
  for (const q of pts) lines.push(`${q[0]},${q[1]}`);
  fs.writeFileSync(process.argv[4], lines.join('\n') + '\n');
}
