// Screenshots of every page for a visual review (not a test).
// usage: [ONLY=unit/] node tests/e2e/screenshots.mjs DIST_DIR OUT_DIR [HEIGHT] [light|dark] [WIDTH]
import { mkdir } from "node:fs/promises";
import { serve, launch, waitForLab } from "./serve.mjs";

const [dist = "dist", out = "target/screenshots", height = "4000", theme = "light", width = "1280"] = process.argv.slice(2);
await mkdir(out, { recursive: true });
const server = await serve(dist);
const browser = await launch();
const context = await browser.newContext({ viewport: { width: Number(width), height: Number(height) }, colorScheme: theme });
const page = await context.newPage();
page.on("console", (m) => { if (m.type() === "error") console.log(`console error: ${m.text()}`); });
await page.goto(`${server.url}#dev`);
await waitForLab(page);
const pages = await page.evaluate(async () => {
  const { lessons } = await import("./pkg/kinolab_js.js").then(async (m) => { await m.default(); return m; });
  return lessons().units.flatMap((u) => u.lessons).map((l) => l.address);
});
// ONLY=<prefix> limits the run to the pages whose address starts with it.
const only = process.env.ONLY;
for (const address of ["", "gallery", ...pages].filter((a) => !only || a.startsWith(only))) {
  await page.goto(`${server.url}#/${address}`);
  await page.waitForFunction((a) => document.documentElement.dataset.kinolabPage === a, address);
  await page.waitForTimeout(400);
  const name = (address || "home").replaceAll("/", "_");
  await page.screenshot({ path: `${out}/${name}-${theme}.png` });
  console.log(`${out}/${name}-${theme}.png`);
}
await browser.close();
await server.close();
