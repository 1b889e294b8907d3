// Benchmarks in headless Chromium, printed beside criterion's native figures.
//
// usage: node tests/e2e/bench.mjs CRITERION_DIR BENCH_WEB_DIR DIST_DIR
import { readFile, readdir, stat, writeFile, mkdir } from "node:fs/promises";
import { gzipSync } from "node:zlib";
import { join } from "node:path";
import { serve, launch, waitForLab, waitForPage } from "./serve.mjs";
import { sizeByCrate } from "./wasm-size.mjs";

const [criterionDir, benchWeb, dist] = process.argv.slice(2);
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
const names = (await page.evaluate(() => window.bench.kernel_names())).split(",");
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

// Size of the lab's wasm and time to first frame (median of 5 cold loads).
const wasmFile = (await readdir(dist)).find((f) => f.endsWith(".wasm") && f.startsWith("kinolab-lab"));
const wasmBytes = await readFile(join(dist, wasmFile));
const labServer = await serve(dist);
const firstFrames = [];
for (let i = 0; i < 5; i++) {
  const context = await browser.newContext({ viewport: { width: 1280, height: 720 } });
  const lab = await context.newPage();
  await lab.goto(`${labServer.url}#dev`);
  await waitForLab(lab);
  firstFrames.push(Number(await lab.evaluate(() => document.documentElement.dataset.kinolabFirstFrameMs)));
  await context.close();
}
// Frame time of every widget, alone in the gallery at 1280×800, while the
// pointer drags across it (and while it animates on its own).
const widgetNames = await (async () => {
  const probe = await browser.newPage();
  await probe.goto(`${labServer.url}#dev`);
  await waitForLab(probe);
  const list = await probe.evaluate(async () => {
    const m = await import("./pkg/kinolab_js.js");
    await m.default();
    return m.widgets().map((w) => w.name);
  });
  await probe.close();
  return list;
})();
const frames = [];
for (const name of widgetNames) {
  const context = await browser.newContext({ viewport: { width: 1280, height: 800 } });
  const lab = await context.newPage();
  await lab.goto(`${labServer.url}#/gallery/${name}`);
  await waitForPage(lab, `gallery/${name}`);
  await lab.waitForTimeout(500);
  await lab.evaluate(() => window.wasmBindings.kinolab_frame_times());
  for (const y of [300, 420, 540]) {
    await lab.mouse.move(420, y);
    await lab.mouse.down();
    for (let i = 1; i <= 40; i++) {
      await lab.mouse.move(420 + 10 * i, y + (i % 10) * 3);
      await lab.waitForTimeout(16);
    }
    await lab.mouse.up();
  }
  await lab.waitForTimeout(500);
  const ms = await lab.evaluate(() => Array.from(window.wasmBindings.kinolab_frame_times()));
  const sorted = [...ms].sort((a, b) => a - b);
  frames.push({ name, count: ms.length, median: median(ms), p95: sorted[Math.floor(0.95 * (sorted.length - 1))] });
  await context.close();
}
await labServer.close();
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
lines.push("");
lines.push(`lab wasm: ${(wasmBytes.length / 1e6).toFixed(2)} MB raw, ${(gzipSync(wasmBytes, { level: 9 }).length / 1e6).toFixed(2)} MB gzipped`);
lines.push("");
lines.push("| widget (gallery, 1280×800, dragged) | frames | median CPU / frame | p95 | median within 4 ms | p95 within 4 ms |");
lines.push("|---|---:|---:|---:|---|---|");
for (const f of frames) {
  lines.push(`| ${f.name} | ${f.count} | ${f.median.toFixed(2)} ms | ${f.p95.toFixed(2)} ms | ${f.median <= 4 ? "yes" : "no"} | ${f.p95 <= 4 ? "yes" : "no"} |`);
}
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
lines.push("");
lines.push(`first frame after navigation: median ${median(firstFrames).toFixed(0)} ms of 5 cold loads (${firstFrames.map((x) => x.toFixed(0)).join(", ")} ms)`);
const report = lines.join("\n");
console.log(report);
await mkdir("target", { recursive: true });
await writeFile("target/bench-report.md", report + "\n");
