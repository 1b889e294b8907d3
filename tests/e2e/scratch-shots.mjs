import { serve, launch, waitForPage } from "./serve.mjs";
const [dist] = process.argv.slice(2);
const server = await serve(dist);
const browser = await launch();
const cases = [
  ["motion-control/programming-the-robot", "park", "fn control(rho, alpha, beta) {\n    let v = 3.0 * rho;\n    let omega = 8.0 * alpha - 1.5 * beta;\n    let over = max(abs(v) / 0.5, abs(omega) / 2.0);\n    if over > 1.0 { v /= over; omega /= over; }\n    [v, omega]\n}\n", "Submit"],
  ["potential-fields/five-primitives", "pull", "fn field(x, y) {\n    [(4.0 - x) * 1e12, -y * 1e12]\n}\n", "Run"],
  ["legged-locomotion/gaits", "walk", "fn foot(leg, phase) {\n    #{ stance: true, at: [leg.x + 0.03 - 0.06 * phase, leg.y, leg.z] }\n}\n", "Run"],
  ["behaviours/coordination", "coord", null, "Run"],
];
for (const [address, name, code, button] of cases) {
  const page = await (await browser.newContext({ viewport: { width: 1280, height: 900 } })).newPage();
  page.on("pageerror", (e) => console.log("pageerror", e.message));
  page.on("console", (m) => { if (m.type() === "error") console.log("console error", m.text()); });
  await page.goto(`${server.url}?a11y#/${address}`);
  await waitForPage(page, address);
  const editor = page.locator("#kinolab-a11y textarea").first();
  await editor.waitFor({ state: "attached", timeout: 10_000 });
  if (code) { await editor.fill(code); await page.waitForTimeout(300); }
  const run = page.getByRole("button", { name: button, exact: true }).first();
  await run.evaluate((e) => e.click());
  await page.waitForTimeout(400);
  for (let i = 0; i < 60; i++) {
    const text = await page.evaluate(() => document.getElementById("kinolab-a11y").innerText);
    if (!/Running your code|Grading your code|Recording/.test(text) && /Not yet|Passed/.test(text)) break;
    await page.waitForTimeout(500);
  }
  // Scroll until the Run button sits near the top of the window.
  for (let i = 0; i < 80; i++) {
    const box = await page.getByRole("button", { name: "Run", exact: true }).first().boundingBox();
    if (box && box.y > 60 && box.y < 260) break;
    await page.mouse.move(1260, 450);
    await page.mouse.wheel(0, box && box.y < 60 ? -200 : 200);
    await page.waitForTimeout(100);
  }
  await page.waitForTimeout(800);
  await page.screenshot({ path: `/tmp/shots/${name}.png` });
  console.log("shot", name);
  await page.close();
}
await browser.close();
await server.close();
