// Long sessions in the browser (a measurement, not part of the test
// command): each widget that runs for long, alone in the gallery, is set
// playing at 4× and left for ten simulated minutes (150 s), and the size
// of the wasm heap is read every 15 s. Linear memory never shrinks, so a
// heap that levels off is one whose high-water mark stopped rising.
// usage: node tests/e2e/soak.mjs SITE_DIR [SECONDS]
import { serve, launch, waitForPage, points } from "./serve.mjs";

const [site = "dist", seconds = "150"] = process.argv.slice(2);
const widgets = ["behaviour-arena", "architecture-arena", "component-lab", "controller-playground"];
const server = await serve(site);
const browser = await launch();

async function press(page, name) {
  for (let i = 0; i < 50; i += 1) {
    const at = (await points(page))[name];
    if (at) {
      await page.mouse.click(at.x, at.y);
      return;
    }
    await page.waitForTimeout(100);
  }
  throw new Error(`no ${name} on the page`);
}

// One page per widget, all at once: each is its own window, so none is
// throttled as a background tab.
const runs = await Promise.all(widgets.map(async (name) => {
  const context = await browser.newContext({ viewport: { width: 1280, height: 1400 } });
  const page = await context.newPage();
  await page.addInitScript(() => {
    addEventListener("TrunkApplicationStarted", (e) => { window.kinolabMemory = e.detail.wasm.memory; });
  });
  await page.goto(`${server.url}?probe#/gallery/${name}`);
  await waitForPage(page, `gallery/${name}`);
  await press(page, "player.speed 4×");
  await press(page, "player.play");
  return { name, page, curve: [] };
}));
const mb = (page) => page.evaluate(() => window.kinolabMemory.buffer.byteLength / 1048576);
for (let t = 0; t <= Number(seconds); t += 15) {
  for (const run of runs) run.curve.push(await mb(run.page));
  if (t < Number(seconds)) await new Promise((r) => setTimeout(r, 15_000));
}
for (const { name, curve } of runs) {
  console.log(`${name}: wasm heap MB every 15 s (60 simulated s at 4×): ${curve.map((m) => m.toFixed(1)).join(" ")}`);
}
await browser.close();
await server.close();
