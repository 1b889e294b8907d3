// Benchmarks in headless Chromium, printed beside criterion's native
// figures, and where the lab's wasm bytes go (frames, start-up and size:
// smooth.mjs).
//
// usage: node tests/e2e/bench.mjs CRITERION_DIR BENCH_WEB_DIR
// (ONLY=regex times only the kernels whose names match)
import { readFile, readdir, stat, writeFile, mkdir } from "node:fs/promises";
import { join } from "node:path";
import { serve, launch } from "./serve.mjs";
import { sizeByCrate } from "./wasm-size.mjs";

const [criterionDir, benchWeb] = process.argv.slice(2);
const median = (xs) => { const s = [...xs].sort((a, b) => a - b); return s[Math.floor(s.length / 2)]; };
const fmt = (ns) => ns >= 1e6 ? `${(ns / 1e6).toFixed(2)} ms` : ns >= 1e3 ? `${(ns / 1e3).toFixed(2)} µs` : `${ns.toFixed(1)} ns`;

// A page that loads the bench module; the harness lives in the page.
await writeFile(join(benchWeb, "index.html"), `<!DOCTYPE html><script type="module">
import init, * as bench from "./kinolab_bench.js";
await init();
window.bench = bench;
window.benchReady = true;
</script>`);

const browser = await launch();
const benchServer = await serve(benchWeb);
const page = await browser.newPage();
await page.goto(benchServer.url);
await page.waitForFunction(() => window.benchReady, null, { timeout: 60_000 });
const only = process.env.ONLY ? new RegExp(process.env.ONLY) : null;
const names = (await page.evaluate(() => window.bench.kernel_names()))
  .split(",")
  .filter((n) => !only || only.test(n));
const rows = [];
for (const name of names) {
  // Warm up first: Chromium starts wasm in its baseline compiler and
  // optimises hot functions in the background, so a kernel measured at
  // once may still run unoptimised code (lesson_parse measured 3× slower
  // that way). Half a second of calls, then a pause for the compiler.
  await page.evaluate((name) => {
    const end = performance.now() + 500;
    while (performance.now() < end) window.bench.run_kernel(name, 1);
  }, name);
  await page.waitForTimeout(200);
  const wasmNs = await page.evaluate((name) => {
    // Calibrate so one sample lasts about 20 ms, then take 15 samples.
    let iterations = 1;
    for (;;) {
      const t0 = performance.now();
      window.bench.run_kernel(name, iterations);
      if (performance.now() - t0 > 20 || iterations > 1e8) break;
      iterations *= 2;
    }
    const samples = [];
    for (let i = 0; i < 15; i++) {
      const t0 = performance.now();
      window.bench.run_kernel(name, iterations);
      samples.push(((performance.now() - t0) * 1e6) / iterations);
    }
    samples.sort((a, b) => a - b);
    return samples[7];
  }, name);
  let nativeNs = NaN;
  try {
    const est = JSON.parse(await readFile(join(criterionDir, name, "new", "estimates.json"), "utf8"));
    nativeNs = est.median.point_estimate;
  } catch { /* no native figure */ }
  rows.push({ name, nativeNs, wasmNs, ratio: wasmNs / nativeNs });
}
await benchServer.close();

// The reference implementation's kernels run natively only.
for (const name of (await readdir(criterionDir)).filter((n) => n.startsWith("k_")).sort()) {
  try {
    const est = JSON.parse(await readFile(join(criterionDir, name, "new", "estimates.json"), "utf8"));
    rows.push({ name, nativeNs: est.median.point_estimate, wasmNs: NaN, ratio: NaN });
  } catch { /* not run */ }
}

await browser.close();

const lines = [];
lines.push("| kernel | native (criterion median) | wasm in Chromium (median) | wasm / native |");
lines.push("|---|---:|---:|---:|");
for (const r of rows) {
  const ratio = Number.isFinite(r.ratio) ? `${r.ratio.toFixed(2)}×` : "—";
  const wasm = Number.isFinite(r.wasmNs) ? fmt(r.wasmNs) : "— (native only)";
  lines.push(`| ${r.name} | ${fmt(r.nativeNs)} | ${wasm} | ${ratio} |`);
}
// Kinolab against the reference, same inputs.
const byName = Object.fromEntries(rows.map((r) => [r.name, r]));
for (const [ours, theirs] of [["mech_fk_puma_tool", "k_fk_puma_tool"], ["mech_ik_puma_100_bent_start", "k_ik_puma_100_targets"]]) {
  if (byName[ours] && byName[theirs]) {
    lines.push("");
    lines.push(`${ours} / ${theirs}: ${(byName[ours].nativeNs / byName[theirs].nativeNs).toFixed(2)}× (native medians)`);
  }
}
try {
  lines.push("");
  lines.push((await readFile("target/ik-survey.md", "utf8")).trimEnd());
} catch { /* no survey */ }
// Where the bytes go (shares from the build before wasm-opt, which keeps names).
try {
  const size = await sizeByCrate("target/wasm32-unknown-unknown/release/kinolab-lab.wasm");
  const total = size.code + size.data;
  const share = (b) => `${(100 * b / total).toFixed(1)} %`;
  lines.push("");
  lines.push("| part of the lab's wasm (before wasm-opt) | KB | share |");
  lines.push("|---|---:|---:|");
  lines.push(`| data (fonts, lessons, tables) | ${(size.data / 1024).toFixed(0)} | ${share(size.data)} |`);
  for (const [crate, bytes] of size.byCrate.slice(0, 20)) {
    lines.push(`| ${crate} | ${(bytes / 1024).toFixed(0)} | ${share(bytes)} |`);
  }
  const rest = size.byCrate.slice(20).reduce((a, [, b]) => a + b, 0);
  lines.push(`| everything else | ${(rest / 1024).toFixed(0)} | ${share(rest)} |`);
} catch (e) { lines.push(`(no size breakdown: ${e.message})`); }
const report = lines.join("\n");
console.log(report);
await mkdir("target", { recursive: true });
await writeFile("target/bench-report.md", report + "\n");
