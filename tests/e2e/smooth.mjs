// Smooth on a slow machine: every gallery widget dragged, and played where
// it simulates, with Chromium's CPU slowed four times, at a laptop's and a
// phone's size; frames per second of every lesson at rest; the wasm heap
// after every lesson; the first frame of five cold loads; the wasm's size.
//
// usage: node tests/e2e/smooth.mjs DIST_DIR [REPORT_FILE]
// (`ONLY=a,b` measures only the widgets named; each row is also appended
// to REPORT_FILE.rows as it is measured, so a long run keeps what it has.)
import { appendFile, readFile, readdir, writeFile } from "node:fs/promises";
import { join } from "node:path";
import { serve, launch, waitForLab, waitForPage } from "./serve.mjs";

const [dist, reportFile = "target/smooth-report.md"] = process.argv.slice(2);
const THROTTLE = 4;
const SIZES = [[1280, 800], [412, 915]];
const median = (xs) => { const s = [...xs].sort((a, b) => a - b); return s[Math.floor(s.length / 2)]; };
const p95 = (xs) => { const s = [...xs].sort((a, b) => a - b); return s[Math.floor(0.95 * (s.length - 1))]; };
const frameTimes = (page) => page.evaluate(() => Array.from(window.wasmBindings.kinolab_frame_times()));

const server = await serve(dist);
const browser = await launch();

/** A fresh page at `width`×`height` on `address`, its CPU slowed `rate` times. */
async function open(address, [width, height], rate) {
  const context = await browser.newContext({ viewport: { width, height } });
  const page = await context.newPage();
  if (rate > 1) {
    const cdp = await context.newCDPSession(page);
    await cdp.send("Emulation.setCPUThrottlingRate", { rate });
  }
  await page.goto(`${server.url}#/${address}`);
  await waitForPage(page, address, 180_000);
  return { page, close: () => context.close() };
}

/** The lab's JS package, for the names of widgets and lessons. */
async function catalogue() {
  const probe = await browser.newPage();
  await probe.goto(`${server.url}#dev`);
  await waitForLab(probe);
  const lists = await probe.evaluate(async () => {
    const m = await import("./pkg/kinolab_js.js");
    await m.default();
    const units = m.lessons().units;
    return { widgets: m.widgets().map((w) => w.name), lessons: units.flatMap((u) => u.lessons.map((l) => l.address)) };
  });
  await probe.close();
  return lists;
}

/** Where the widget's Play button is, read from the screen-reader mirror
 * of an unthrottled copy of the page (the mirror costs frame time, so the
 * timed page runs without it); `{ playing: true }` when it plays by
 * itself (its button says Pause); null when it has no player. */
async function playButton(address, size) {
  const { page, close } = await open(address, size, 1);
  await page.focus("#kinolab-a11y-on");
  await page.keyboard.press("Enter");
  await page.waitForTimeout(800);
  const at = await page.evaluate(() => {
    const button = (name) => document.querySelector(`#kinolab-a11y button[aria-label="${name}"]`);
    const b = button("Play");
    if (!b) return button("Pause") ? { playing: true } : null;
    const r = b.getBoundingClientRect();
    return { x: r.x + r.width / 2, y: r.y + r.height / 2 };
  });
  await close();
  return at;
}

/** Frame times of a widget dragged across three lines, then played. */
async function measure(name, size) {
  const address = `gallery/${name}`;
  const play = await playButton(address, size);
  const { page, close } = await open(address, size, THROTTLE);
  const [w, h] = size;
  await page.waitForTimeout(1000);
  await frameTimes(page);
  for (const y of [0.375, 0.525, 0.675].map((f) => Math.round(f * h))) {
    const x0 = Math.round(0.3 * w);
    await page.mouse.move(x0, y);
    await page.mouse.down();
    for (let i = 1; i <= 30; i++) {
      await page.mouse.move(x0 + Math.round((0.4 * w * i) / 30), y + (i % 10) * 3);
      await page.waitForTimeout(16);
    }
    await page.mouse.up();
  }
  const dragged = await frameTimes(page);
  let played = [];
  if (play) {
    if (!play.playing) await page.mouse.click(play.x, play.y);
    await page.waitForTimeout(3000);
    played = await frameTimes(page);
  }
  await close();
  return { name, size, dragged, played, plays: Boolean(play) };
}

/** Frames a lesson draws in two seconds after a second at rest. */
async function atRest(page, address) {
  await page.evaluate((a) => { location.hash = `#/${a}`; }, address);
  await waitForPage(page, address);
  await page.waitForTimeout(1000);
  await frameTimes(page);
  await page.waitForTimeout(2000);
  return (await frameTimes(page)).length / 2;
}

const ms = (x) => (x === undefined ? "—" : `${x.toFixed(1)} ms`);
/** A widget's row of the frame table. */
function row(r) {
  const all = [...r.dragged, ...r.played];
  const ok = all.length > 0 && median(all) <= 16.7 && p95(all) <= 33;
  const play = r.plays ? [r.played.length, ms(median(r.played)), ms(p95(r.played))] : ["—", "—", "—"];
  return `| ${r.name} | ${r.size.join("×")} | ${r.dragged.length} | ${ms(median(r.dragged))} | ${ms(p95(r.dragged))} | ${play.join(" | ")} | ${ok ? "yes" : "no"} |`;
}

const { widgets, lessons } = await catalogue();
const only = process.env.ONLY?.split(",");
const rows = [];
await writeFile(`${reportFile}.rows`, "");
for (const name of widgets.filter((n) => !only || only.includes(n))) {
  for (const size of SIZES) {
    rows.push(await measure(name, size));
    console.error(row(rows.at(-1)));
    await appendFile(`${reportFile}.rows`, `${row(rows.at(-1))}\n`);
  }
}

// Every lesson once in one session: frames at rest, then the heap.
const session = await open(lessons[0], SIZES[0], 1);
const rest = [];
for (const address of lessons) rest.push({ address, fps: await atRest(session.page, address) });
const heapMb = (await session.page.evaluate(() => window.wasmBindings.kinolab_heap_bytes())) / 2 ** 20;
await session.close();

// Five cold loads: the first frame after navigation.
const firstFrames = [];
for (let i = 0; i < 5; i++) {
  const context = await browser.newContext({ viewport: { width: 1280, height: 720 } });
  const page = await context.newPage();
  await page.goto(`${server.url}#dev`);
  await waitForLab(page);
  firstFrames.push(Number(await page.evaluate(() => document.documentElement.dataset.kinolabFirstFrameMs)));
  await context.close();
}
await server.close();
await browser.close();

const wasmFile = (await readdir(dist)).find((f) => f.endsWith(".wasm") && f.startsWith("kinolab-lab"));
const wasm = await readFile(join(dist, wasmFile));
// The copies a host sends (web/precompress.mjs wrote them beside the wasm).
const sent = async (suffix) => (await readFile(join(dist, wasmFile + suffix))).length;

const lines = [`CPU slowed ${THROTTLE}× (DevTools' Emulation.setCPUThrottlingRate); frame = the CPU time eframe reports.`, ""];
lines.push("| widget | size | dragged: frames | median | p95 | played: frames | median | p95 | within 16.7 / 33 ms |");
lines.push("|---|---|---:|---:|---:|---:|---:|---:|---|");
lines.push(...rows.map(row));
const busy = rest.filter((r) => r.fps > 0);
lines.push("");
lines.push(`lessons at rest: ${rest.length - busy.length} of ${rest.length} draw no frames after a second without input${busy.length ? ` (busy: ${busy.map((r) => `${r.address} ${r.fps} fps`).join(", ")})` : ""}`);
lines.push(`wasm heap after opening every lesson once: ${heapMb.toFixed(1)} MB`);
lines.push(`first frame after navigation: median ${median(firstFrames).toFixed(0)} ms of 5 cold loads (${firstFrames.map((x) => x.toFixed(0)).join(", ")} ms)`);
const mb = (n) => (n / 1e6).toFixed(2);
lines.push(`lab wasm: ${mb(wasm.length)} MB raw, ${mb(await sent(".gz"))} MB gzip, ${mb(await sent(".br"))} MB Brotli`);
const report = lines.join("\n");
console.log(report);
await writeFile(reportFile, report + "\n");
