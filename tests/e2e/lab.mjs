// End-to-end: the built lab in headless Chromium, as a learner opens it.
//
// usage: node tests/e2e/lab.mjs DIST_DIR OUT_DIR
// Serves DIST_DIR, opens a lesson by deep link, reloads, goes back and
// forward, goes offline and reloads, takes screenshots into OUT_DIR, and
// fails on any console error, page error or panic text.
import { cp, mkdir, readFile, readdir, rename, rm, writeFile } from "node:fs/promises";
import { execFileSync } from "node:child_process";
import assert from "node:assert/strict";
import { serve, launch, waitForLab, waitForPage, points } from "./serve.mjs";

const [dist = "dist", out = "target/e2e"] = process.argv.slice(2);
await mkdir(out, { recursive: true });
const server = await serve(dist);
const browser = await launch();
const problems = [];
let passed = 0;
let failed = 0;

// Scroll the lesson (mouse wheel at the page's left margin) until `name`
// is well inside the window.
async function bringIntoView(page, name) {
  const { height } = page.viewportSize();
  let last = null;
  for (let i = 0; i < 60; i += 1) {
    const at = (await points(page))[name];
    // At the end of the page it cannot come further in: take it on screen.
    const stuck = at && last && at.y === last.y && at.y > 20 && at.y < height - 20;
    last = at;
    if (stuck || (at && at.y > 200 && at.y < height - 200)) {
      // The page glides to a stop: aim once it stands still.
      await page.waitForTimeout(500);
      const still = (await points(page))[name];
      if (still.x === at.x && still.y === at.y) return at;
      continue;
    }
    // The page's right margin: over the lesson, clear of any widget.
    const { width } = page.viewportSize();
    await page.mouse.move(width - 12, height / 2);
    await page.mouse.wheel(0, at && at.y <= 200 ? -150 : 150);
    await page.waitForTimeout(120);
  }
  throw new Error(`${name} never came into view: ${JSON.stringify(await points(page))}`);
}

// The widget states in the address, as the text they carry (version `b`:
// settings lines; `a`: postcard, whose strings are plain UTF-8 too).
async function widgetStates(page) {
  const hash = await page.evaluate(() => location.hash);
  const query = hash.split("?")[1] || "";
  return query.split("&").map((kv) => kv.split("=")[1] || "")
    .filter((v) => /^[ab]/.test(v)).map((v) => Buffer.from(v.slice(1), "base64url").toString());
}

const wiringLesson = "component-patterns/dynamic-wiring";
async function assertWired(page) {
  await page.waitForTimeout(400);
  const states = await widgetStates(page);
  assert.ok(states.some((s) => s.includes("motion.source") && s.includes("planner.route")),
    `no connect in the address: ${JSON.stringify(states)} (${await page.evaluate(() => location.hash)})`);
}

async function check(name, fn) {
  // ONLY=text runs just the checks whose names contain it (while working on one).
  if (process.env.ONLY && !name.includes(process.env.ONLY)) return;
  try {
    await fn();
    passed += 1;
    console.log(`ok   ${name}`);
  } catch (e) {
    failed += 1;
    console.log(`FAIL ${name}: ${e.message}`);
  }
}

try {
  const context = await browser.newContext({ viewport: { width: 1280, height: 720 } });
  const page = await context.newPage();
  // Every console error, page error and failed request counts, except the
  // requests made on purpose while the network is off.
  let offline = false;
  const watch = (p, name) => {
    p.on("console", (m) => { if (m.type() === "error" && !(offline && /Failed to load resource|ERR_INTERNET_DISCONNECTED/.test(m.text()))) problems.push(`${name} console error: ${m.text()}`); });
    p.on("pageerror", (e) => problems.push(`${name} page error: ${e.message}`));
    p.on("response", (r) => { if (r.status() >= 400) problems.push(`${name}: ${r.status()} for ${r.url()}`); });
    p.on("requestfailed", (r) => { if (!offline) problems.push(`${name}: request failed for ${r.url()} (${r.failure()?.errorText})`); });
  };
  watch(page, "lab");

  const lesson = "automation/ways-to-move";
  await check("a deep link opens its lesson on the first frame", async () => {
    await page.goto(`${server.url}#/${lesson}`);
    assert.equal(await waitForLab(page), lesson);
    assert.match(await page.title(), /Ways .* Kinolab|· Kinolab/);
    await page.waitForTimeout(500);
    await page.screenshot({ path: `${out}/lesson.png` });
  });

  await check("the lesson is still there after a reload", async () => {
    await page.reload();
    assert.equal(await waitForLab(page), lesson);
  });

  await check("back and forward follow the history", async () => {
    await page.evaluate(() => { location.hash = "#/automation/open-and-closed-worlds"; });
    await page.waitForFunction(() => document.documentElement.dataset.kinolabPage === "automation/open-and-closed-worlds");
    await page.goBack();
    await page.waitForFunction((l) => document.documentElement.dataset.kinolabPage === l, lesson);
    await page.goForward();
    await page.waitForFunction(() => document.documentElement.dataset.kinolabPage === "automation/open-and-closed-worlds");
  });

  await check("the home page renders", async () => {
    await page.goto(`${server.url}`);
    assert.equal(await waitForLab(page), "");
    await page.waitForTimeout(300);
    await page.screenshot({ path: `${out}/home.png` });
  });

  await check("a widget's state in a link is restored and kept in the address", async () => {
    // The leg-events widget (the lesson's first widget, w0) set to five
    // legs. A link of the first format (postcard: 5 is the byte 0x05,
    // base64url "BQ", after the format letter "a") still opens, and the
    // address then shows the settings in today's format: the letter "b"
    // and the settings' text, base64url-encoded.
    const lesson = "legged-locomotion/legs-and-wheels";
    const now = `?w0=b${Buffer.from("legs: 5\n").toString("base64url")}`;
    await page.goto(`${server.url}#/${lesson}?w0=aBQ`);
    await waitForPage(page, lesson);
    await page.waitForTimeout(500);
    assert.equal(await page.evaluate(() => location.hash), `#/${lesson}${now}`);
    await page.reload();
    assert.equal(await waitForLab(page), lesson);
    await page.waitForTimeout(300);
    assert.equal(await page.evaluate(() => location.hash), `#/${lesson}${now}`);
    // A damaged state is dropped: the widget starts as the lesson set it up.
    await page.goto(`${server.url}#/${lesson}?w0=zzz`);
    await waitForPage(page, lesson);
    await page.waitForTimeout(500);
    assert.equal(await page.evaluate(() => location.hash), `#/${lesson}`);
  });

  await check("a lab opened once works offline", async () => {
    await page.evaluate(() => navigator.serviceWorker.ready);
    await page.reload();            // now controlled by the service worker, which caches
    await waitForLab(page);
    await page.waitForTimeout(500);
    await context.setOffline(true);
    offline = true;
    try {
      // Leave the lab first: a jump that only changes the hash would stay in
      // the same document and never ask the service worker for anything.
      await page.goto("about:blank");
      await page.goto(`${server.url}#/${lesson}`);
      assert.equal(await waitForLab(page), lesson);
    } finally {
      await context.setOffline(false);
      offline = false;
    }
  });

  // Progress: each check below opens its own browser context, so its own
  // storage, like another browser or another computer.
  const fresh = () => browser.newContext({ viewport: { width: 1280, height: 720 }, acceptDownloads: true });
  const stored = (p) => p.evaluate(() => JSON.parse(localStorage.getItem("kinolab.progress") || "null"));
  const opened = (p, n) => p.waitForFunction((n) => document.documentElement.dataset.kinolabOpened === n, String(n));

  await check("two tabs keep both tabs' progress", async () => {
    const both = await fresh();
    try {
      const [first, second] = [await both.newPage(), await both.newPage()];
      watch(first, "tab 1");
      watch(second, "tab 2");
      // Tab 2 opens before tab 1 has done anything.
      await second.goto(server.url);
      await waitForLab(second);
      await first.goto(`${server.url}#/automation/ways-to-move`);
      await waitForLab(first);
      await first.waitForFunction(() => (localStorage.getItem("kinolab.progress") || "").includes("ways-to-move"));
      // Tab 2 hears of it without a reload, and what it stores next keeps it.
      await opened(second, 1);
      await second.evaluate(() => { location.hash = "#/behaviours/emergence"; });
      await waitForPage(second, "behaviours/emergence");
      await second.waitForFunction(() => (localStorage.getItem("kinolab.progress") || "").includes("behaviours/emergence"));
      assert.deepEqual((await stored(second)).visited, ["automation/ways-to-move", "behaviours/emergence"]);
      await opened(first, 2);
    } finally {
      await both.close();
    }
  });

  await check("progress saved as a file loads in another browser; a foreign file is refused", async () => {
    const [home, away] = [await fresh(), await fresh()];
    try {
      const here = await home.newPage();
      watch(here, "saving");
      await here.goto(`${server.url}?probe#/automation/ways-to-move`);
      await waitForLab(here);
      await here.evaluate(() => { location.hash = "#/"; });
      await waitForPage(here, "");
      const save = await bringIntoView(here, "progress.save");
      const [download] = await Promise.all([here.waitForEvent("download"), here.mouse.click(save.x, save.y)]);
      assert.equal(download.suggestedFilename(), "kinolab-progress.json");
      const text = await readFile(await download.path(), "utf8");
      assert.match(text, /"kind": "kinolab-progress"/);

      // The browser's own file dialog cannot be driven headless from every
      // page, so the page's file input is handed the file as if chosen:
      // everything after the dialog (reading, checking, merging) is the lab's.
      await away.addInitScript(() => {
        const click = HTMLInputElement.prototype.click;
        HTMLInputElement.prototype.click = function () {
          const chosen = window.kinolabNextFile;
          if (this.type !== "file" || !chosen) return click.call(this);
          window.kinolabNextFile = null;
          const files = new DataTransfer();
          files.items.add(new File([chosen.body], chosen.name, { type: "application/json" }));
          this.files = files.files;
          this.dispatchEvent(new Event("change"));
        };
      });
      const there = await away.newPage();
      watch(there, "loading");
      await there.goto(`${server.url}?probe`);
      await waitForLab(there);
      const give = async (name, body) => {
        await there.evaluate((file) => { window.kinolabNextFile = file; }, { name, body });
        const load = await bringIntoView(there, "progress.load");
        await there.mouse.click(load.x, load.y);
        await there.waitForFunction(() => window.kinolabNextFile === null, null, { timeout: 10_000 });
      };
      const notice = (start) => there.waitForFunction((s) => (document.documentElement.dataset.kinolabNotice || "").startsWith(s), start);
      await give("kinolab-progress.json", text);
      await notice("Loaded kinolab-progress.json: 1 lesson opened.");
      await there.waitForFunction(() => (localStorage.getItem("kinolab.progress") || "").includes("ways-to-move"));
      const before = await stored(there);
      await give("notes.json", '{"version":2,"visited":["a/b"]}');
      await notice("notes.json was not loaded: it is not a Kinolab progress file.");
      assert.deepEqual(await stored(there), before);
    } finally {
      await home.close();
      await away.close();
    }
  });

  await check("progress stored by the first version is read into today's format", async () => {
    const old = await fresh();
    try {
      const v1 = await readFile("crates/show/app/src/progress/fixtures/v1.json", "utf8");
      const p = await old.newPage();
      watch(p, "migrating");
      // The first version's progress appears under a running lab (as if an
      // old copy wrote it); leaving the page must not write over it.
      await p.goto(server.url);
      await waitForLab(p);
      await p.evaluate((v1) => localStorage.setItem("kinolab.progress", v1), v1);
      await p.goto(`${server.url}#/behaviours/emergence`);
      await waitForPage(p, "behaviours/emergence");
      await p.waitForFunction(() => (localStorage.getItem("kinolab.progress") || "").includes('"version":2'));
      await p.waitForLoadState("networkidle");
      await p.reload();
      await waitForLab(p);
      await opened(p, 5);
      const now = await stored(p);
      assert.ok(now.visited.includes("legged-locomotion/legs-and-wheels"), JSON.stringify(now.visited));
      assert.equal(now.quizzes["wheeled-locomotion/wheel-kinds#0"].attempts, 2);
    } finally {
      await old.close();
    }
  });

  await check("a browser that refuses storage: the lab works and says so once", async () => {
    const blocked = await fresh();
    try {
      await blocked.addInitScript(() => {
        Storage.prototype.setItem = function () {
          throw new DOMException("The quota has been exceeded.", "QuotaExceededError");
        };
      });
      const p = await blocked.newPage();
      watch(p, "no storage");
      await p.goto(`${server.url}?probe#/automation/ways-to-move`);
      await waitForLab(p);
      await p.waitForFunction(() => (document.documentElement.dataset.kinolabNotice || "").includes("not keeping your progress"));
      const at = (await points(p))["notice.save"];
      assert.ok(at, "the notice offers the progress file");
      const [download] = await Promise.all([p.waitForEvent("download"), p.mouse.click(at.x, at.y)]);
      assert.match(await readFile(await download.path(), "utf8"), /ways-to-move/);
      await p.evaluate(() => { location.hash = "#/behaviours/emergence"; });
      assert.equal(await waitForPage(p, "behaviours/emergence"), "behaviours/emergence");
    } finally {
      await blocked.close();
    }
  });

  await check("the behaviour and potential-field lessons open with their widgets", async () => {
    for (const address of ["behaviours/coordination", "behaviours/building-in-layers", "potential-fields/local-minima", "potential-fields/ways-out"]) {
      await page.goto(`${server.url}#/${address}`);
      await waitForPage(page, address);
      await page.waitForTimeout(800);
    }
    await page.screenshot({ path: `${out}/ways-out.png` });
  });

  await check("a screen reader finds headings, quiz options and formulas in words, and can answer", async () => {
    const reader = await context.newPage();
    watch(reader, "screen reader");
    const address = "wheeled-locomotion/wheel-kinds";
    // Off by default: the page holds no mirror until support is turned on.
    await reader.goto(`${server.url}#/${address}`);
    await waitForPage(reader, address);
    await reader.waitForTimeout(300);
    assert.equal(await reader.locator("#kinolab-a11y [data-node]").count(), 0);
    // The page's first element turns it on (first in a screen reader's
    // reading order; the canvas keeps Tab for the lab's own focus order).
    assert.equal(await reader.evaluate(() => document.body.firstElementChild.id), "kinolab-a11y-on");
    await reader.focus("#kinolab-a11y-on");
    await reader.keyboard.press("Enter");
    await reader.waitForFunction(() => document.querySelectorAll("#kinolab-a11y [data-node]").length > 50);
    assert.ok(await reader.getByRole("heading").count() >= 5, "headings");
    const option = reader.getByRole("radio", { name: "A steered standard wheel" });
    assert.equal(await option.count(), 1, "a quiz option by its name");
    assert.ok(await reader.getByText("r phi dot", { exact: true }).count() >= 1, "a formula in words");
    // Choosing the option as a screen reader does (a click on the element)
    // reaches the lab.
    await option.evaluate((e) => e.click());
    await reader.waitForFunction(() => document.querySelector('#kinolab-a11y [aria-label="A steered standard wheel"]')?.getAttribute("aria-checked") === "true");
    // No keyboard trap: Escape, then Shift+Tab, leaves the canvas.
    await reader.focus("#kinolab-canvas");
    await reader.keyboard.press("Escape");
    await reader.keyboard.press("Shift+Tab");
    assert.equal(await reader.evaluate(() => document.activeElement.id), "kinolab-a11y-on");
    // One lesson per unit: headings, quiz options and, for every widget on
    // the page, its description of what it shows.
    for (const address of ["automation/open-and-closed-worlds", "wheeled-locomotion/wheel-kinds", "motion-control/open-loop",
      "mechanisms/one-model-for-every-mechanism", "behaviours/what-a-behaviour-is", "potential-fields/five-primitives",
      "legged-locomotion/legs-and-wheels", "architectures/what-an-architecture-is", "component-patterns/components",
      "software-stability/what-stability-means"]) {
      await reader.goto(`${server.url}#/${address}`);
      await waitForPage(reader, address);
      await reader.waitForFunction(() => document.querySelectorAll('#kinolab-a11y [role="group"]').length > 0, null, { timeout: 5000 })
        .catch(() => { throw new Error(`${address}: no widget says what it shows`); });
      const groups = await reader.locator('#kinolab-a11y [role="group"]').evaluateAll((es) => es.map((e) => e.getAttribute("aria-label") ?? ""));
      assert.ok(groups.every((name) => name.length > 20), `${address}: a widget without a description: ${JSON.stringify(groups)}`);
      assert.ok(await reader.getByRole("heading").count() >= 2, `${address}: headings`);
      assert.ok(await reader.locator('#kinolab-a11y [role="radio"], #kinolab-a11y [role="checkbox"]').count() >= 1, `${address}: quiz options`);
    }
    // The code editor is a real text field in the mirror: it reads the
    // starter code, and an edit typed there reaches the lab (the code goes
    // into the address, as an edit on the canvas does).
    const coding = "motion-control/programming-the-robot";
    await reader.goto(`${server.url}#/${coding}`);
    await waitForPage(reader, coding);
    const editor = reader.locator("#kinolab-a11y textarea").first();
    await editor.waitFor({ state: "attached", timeout: 10_000 });
    assert.match(await editor.inputValue(), /fn \w+\(/, "the starter code");
    const edited = `${await editor.inputValue()}\n// typed through the screen reader\n`;
    await editor.fill(edited);
    await reader.waitForFunction(() => location.hash.includes("?w"), null, { timeout: 10_000 });
    await reader.locator("#kinolab-a11y-on").focus();
    await reader.waitForTimeout(300);
    assert.equal(await editor.inputValue(), edited, "the lab's text, back in the field");
    await reader.close();
  });

  await check("a learner's runaway script never takes the page down", async () => {
    // Code exercises run in a worker of their own: scripts that nest a
    // list thousands deep, or that run until their deadline, end with a
    // message at the line; meanwhile the page answers, and a lesson link
    // works at once.
    const coder = await context.newPage();
    watch(coder, "code exercise");
    const coding = "motion-control/programming-the-robot";
    await coder.goto(`${server.url}?a11y#/${coding}`);
    await waitForPage(coder, coding);
    const editor = coder.locator("#kinolab-a11y textarea").first();
    await editor.waitFor({ state: "attached", timeout: 10_000 });
    const mirrored = () => coder.evaluate(() => document.getElementById("kinolab-a11y").innerText);
    const run = async (code) => {
      await editor.fill(code);
      await coder.waitForTimeout(300);
      await coder.getByRole("button", { name: "Run", exact: true }).first().evaluate((e) => e.click());
    };
    const law = (body) => `fn control(rho, alpha, beta) {\n${body}\n[0.0, 0.0]\n}`;
    for (const body of ["let a = []; for i in 0..5000 { a = [a]; }", "let a = []; loop { a = [a]; }"]) {
      await run(law(body));
      await coder.waitForFunction(() => /a list of more than 1 000 items/.test(document.getElementById("kinolab-a11y").innerText), null, { timeout: 60_000 });
      assert.match(await mirrored(), /line 2, column \d+/);
    }
    // A script that runs until its deadline; while it runs, another lesson.
    await run(law("let a = []; a.pad(999, 1.5); let n = 0; while n < 10000 { let b = a; n += 1; }"));
    await coder.waitForFunction(() => /Running your code/.test(document.getElementById("kinolab-a11y").innerText), null, { timeout: 10_000 });
    const elsewhere = "motion-control/choosing-gains";
    const asked = Date.now();
    // The lesson list's link, clicked as a screen reader clicks it.
    await coder.getByRole("button", { name: "○ Choosing the gains", exact: true }).evaluate((e) => e.click());
    await waitForPage(coder, elsewhere, 5_000);
    assert.ok(Date.now() - asked < 5_000, "the page answered while the code ran");
    await coder.goBack();
    await waitForPage(coder, coding);
    const shown = await coder.evaluate(() => document.getElementById("kinolab-error").style.display);
    assert.notEqual(shown, "block", "no error box");
    await coder.close();
  });

  await check("no error box and no panic text", async () => {
    const text = await page.evaluate(() => document.body.innerText);
    assert.ok(!/panicked|internal error|could not start/i.test(text), text);
    const errorShown = await page.evaluate(() => document.getElementById("kinolab-error").style.display === "block");
    assert.equal(errorShown, false);
  });

  const embed = await context.newPage();
  watch(embed, "embed");
  await check("the JS package works in the embed page", async () => {
    await embed.goto(`${server.url}embed.html`);
    await embed.waitForFunction(() => document.documentElement.dataset.kinolabEmbedReady, null, { timeout: 30_000 });
    assert.equal(await embed.textContent("#legs-out"), "N = (2k − 1)! = 39916800");
    assert.match(await embed.textContent("#stability-out"), /^Statically stable, margin 18\.0 cm$/);
    assert.equal(await embed.textContent("#robot-out"), "δm = 1, δs = 1, δM = 2, DOF = 3, not holonomic; ICR: infinity");
    await embed.selectOption("#robot", "ackermann-car");
    assert.equal(await embed.textContent("#robot-out"), "δm = 1, δs = 1, δM = 2, DOF = 3, not holonomic; ICR at (0.00, 2.50)");
    assert.match(await embed.textContent("#drive-out"), /^Gains strongly stable; reached the goal in 5\.8\d s over \d\.\d\d m$/);
    await embed.fill("#gains", "3, 2, -1.5");
    assert.match(await embed.textContent("#drive-out"), /^Gains unstable; not reached: \d+\.\d cm and \d+° off after 10 s$/);
    assert.equal(await embed.textContent("#fk-out"), "Puma 560: tool at (0.399, -0.150, 1.311) m");
    assert.match(await embed.textContent("#ik-out"), /^Reached: q = \(/);
    await embed.fill("#reach", "3, 0, 0.7");
    assert.match(await embed.textContent("#ik-out"), /^Out of reach: \d+\.\d cm short$/);
    await embed.selectOption("#mechanism", "planar-2r");
    assert.equal(await embed.inputValue("#joints"), "0.00, 0.00");
    assert.equal(await embed.textContent("#fk-out"), "Planar 2R arm: tool at (1.800, 0.000, 0.000) m");
    assert.equal(await embed.textContent("#field-out"), "A U-shaped wall: trapped at (3.75, 0.00)");
    await embed.selectOption("#field", "rock-on-the-axis");
    assert.equal(await embed.textContent("#field-out"), "A rock on the axis: no trap");
    await embed.fill("#com", "0.05");
    assert.equal(await embed.textContent("#stability-out"),
      "Type two numbers for the centre of mass (x, y), separated by commas, for example 0.05, 0.02.");
    await embed.screenshot({ path: `${out}/embed.png`, fullPage: true });
  });

  // A phone and two desktop windows: the lessons with the widest widgets
  // must fit the window (the app reports how far right its content reaches
  // and the screen's edge); the phone with touch input and no console
  // errors. (A UI test checks every page at these widths.)
  const wide = ["wheeled-locomotion/icr-and-holonomy", "motion-control/feedback-and-polar-coordinates",
    "legged-locomotion/gaits", "legged-locomotion/central-pattern-generators",
    "software-stability/analysis-patterns", "component-patterns/dynamic-wiring"];
  await check("a port is wired by a mouse drag at a normal speed", async () => {
    const desk = await (await browser.newContext({ viewport: { width: 1280, height: 800 } })).newPage();
    watch(desk, "wiring");
    await desk.goto(`${server.url}?probe#/${wiringLesson}`);
    await waitForPage(desk, wiringLesson);
    const from = await bringIntoView(desk, "port motion.source");
    const to = (await points(desk))["service planner.route"];
    // About a quarter of a second from press to release.
    await desk.mouse.move(from.x, from.y);
    await desk.mouse.down();
    await desk.mouse.move(to.x, to.y, { steps: 8 });
    await desk.mouse.up();
    await assertWired(desk);
    await desk.screenshot({ path: `${out}/wired-by-mouse.png` });
    await desk.close();
  });

  for (const width of [1024, 1280]) {
    const desk = await (await browser.newContext({ viewport: { width, height: 800 } })).newPage();
    watch(desk, `${width} px`);
    for (const lesson of wide) {
      await check(`${lesson} fits a ${width} px wide window`, async () => {
        await desk.goto(`${server.url}#/${lesson}`);
        await waitForPage(desk, lesson);
        await desk.waitForTimeout(300);
        const [right, edge] = (await desk.evaluate(() => document.documentElement.dataset.kinolabExtent)).split(" ").map(Number);
        assert.ok(edge > 500 && edge <= width, `screen ${edge}`);
        assert.ok(right <= edge + 0.5, `content reaches ${right} on a ${edge} wide screen`);
      });
    }
    await desk.close();
  }
  const phone = await browser.newContext({ viewport: { width: 412, height: 915 }, hasTouch: true, isMobile: true });
  const small = await phone.newPage();
  watch(small, "phone");
  for (const lesson of wide) {
    await check(`${lesson} fits a 412 px wide phone`, async () => {
      await small.goto(`${server.url}#/${lesson}`);
      await waitForPage(small, lesson);
      await small.waitForTimeout(400);
      const [right, screen] = (await small.evaluate(() => document.documentElement.dataset.kinolabExtent)).split(" ").map(Number);
      assert.ok(screen > 300 && screen <= 412, `screen ${screen}`);
      assert.ok(right <= screen + 0.5, `content reaches ${right} on a ${screen} wide screen`);
      await small.screenshot({ path: `${out}/phone-${lesson.split("/")[1]}.png` });
    });
  }
  await check("a finger drags and pinches on the phone without console errors", async () => {
    // Real touch events (what a finger sends), through the DevTools protocol.
    const cdp = await phone.newCDPSession(small);
    const touch = (type, points) => cdp.send("Input.dispatchTouchEvent", { type, touchPoints: points });
    // The first finger drag, over the lesson's text, scrolls the lesson
    // (it does not select text); then two fingers pinch.
    const before = await small.screenshot();
    await touch("touchStart", [{ x: 200, y: 600, id: 1 }]);
    for (let y = 580; y >= 300; y -= 20) {
      await touch("touchMove", [{ x: 200, y, id: 1 }]);
      await small.waitForTimeout(16);
    }
    await touch("touchEnd", []);
    await small.waitForTimeout(500);
    assert.notDeepEqual(await small.screenshot(), before, "the first finger drag over text did not scroll the lesson");
    await touch("touchStart", [{ x: 180, y: 500, id: 1 }, { x: 230, y: 500, id: 2 }]);
    for (let d = 60; d <= 140; d += 20) await touch("touchMove", [{ x: 205 - d, y: 500, id: 1 }, { x: 205 + d, y: 500, id: 2 }]);
    await touch("touchEnd", []);
    await small.waitForTimeout(300);
    const [right, screen] = (await small.evaluate(() => document.documentElement.dataset.kinolabExtent)).split(" ").map(Number);
    assert.ok(right <= screen + 0.5, `after the gestures the content reaches ${right} on a ${screen} wide screen`);
  });

  await check("a finger wires a port on the phone", async () => {
    await small.goto(`${server.url}?probe#/${wiringLesson}`);
    await waitForPage(small, wiringLesson);
    const from = await bringIntoView(small, "port motion.source");
    const to = (await points(small))["service planner.route"];
    const cdp = await phone.newCDPSession(small);
    const touch = (type, points) => cdp.send("Input.dispatchTouchEvent", { type, touchPoints: points });
    await touch("touchStart", [{ x: from.x, y: from.y, id: 1 }]);
    for (let i = 1; i <= 8; i += 1) {
      const f = i / 8;
      await touch("touchMove", [{ x: from.x + (to.x - from.x) * f, y: from.y + (to.y - from.y) * f, id: 1 }]);
      await small.waitForTimeout(16);
    }
    await touch("touchEnd", []);
    await assertWired(small);
    await small.screenshot({ path: `${out}/wired-by-finger.png` });
  });

  await check("damaged links to lessons with widgets open the lesson, never a frozen or broken tab", async () => {
    // A seeded set (the native widget fuzz runs 100 000 cases): for each
    // lesson, every widget slot gets a state cut short, altered, of the
    // first format, hostile, or garbage.
    let seed = 20261204;
    const random = () => { seed = (seed * 1103515245 + 12345) % 2147483648; return seed / 2147483648; };
    const b = (text) => `b${Buffer.from(text).toString("base64url")}`;
    const damaged = [
      () => b("@t: 3600\n"),
      () => b(`speed: 1e308\nlegs: -1\nsize: NaN\n@t: ${(random() * 60).toFixed(2)}\n`),
      () => b("x".repeat(5000)),
      () => b("@events: [[[[[[[[[[[[[[[[]]]]]]]]]]]]]]]]\n"),
      () => `a${Buffer.from(Array.from({ length: 24 }, () => Math.floor(random() * 256))).toString("base64url")}`,
      () => b("legs: 5\n@t: 2\n").slice(0, 1 + Math.floor(random() * 12)),
      () => "%%%",
      () => "b" + "A".repeat(9000),
    ];
    for (const lesson of [...wide, "legged-locomotion/legs-and-wheels", "behaviours/emergence", "software-stability/the-ant-on-the-beach", "motion-control/programming-the-robot"]) {
      const query = [0, 1, 2, 3].map((w) => `w${w}=${damaged[Math.floor(random() * damaged.length)]()}`).join("&");
      await page.goto(`${server.url}#/${lesson}?${query}`);
      assert.equal(await waitForPage(page, lesson, 30_000), lesson);
      // Still drawing: the next frame comes.
      await page.waitForTimeout(300);
      assert.equal(await page.evaluate(() => document.documentElement.dataset.kinolabPage), lesson);
    }
  });

  await check("a new release is offered, and replaces the old one whole when the learner agrees", async () => {
    // Release B: release A's files under the new names a rebuild gives them,
    // its page marked, its service worker stamped with its own version.
    const b = `${out}/release-b`;
    await rm(b, { recursive: true, force: true });
    await cp(dist, b, { recursive: true });
    let index = await readFile(`${b}/index.html`, "utf8");
    const stem = /kinolab-lab-[0-9a-f]+/.exec(index)[0];
    for (const name of await readdir(b)) {
      if (name.startsWith(stem)) await rename(`${b}/${name}`, `${b}/${name.replace(stem, "kinolab-lab-b0b0b0b0")}`);
    }
    index = index.replaceAll(stem, "kinolab-lab-b0b0b0b0").replace("<head>", '<head><meta name="kinolab-release" content="B">');
    await writeFile(`${b}/index.html`, index);
    await rm(`${b}/index.html.br`, { force: true });
    await rm(`${b}/index.html.gz`, { force: true });
    execFileSync("node", ["web/stamp-sw.mjs", b]);

    const release = (p) => p.evaluate(() => document.querySelector('meta[name="kinolab-release"]')?.content ?? "A");
    const banner = (p) => p.waitForSelector("#kinolab-update:not([hidden])", { timeout: 30_000 });
    const context = await fresh();
    try {
      const p = await context.newPage();
      watch(p, "release");
      await p.goto(`${server.url}#/automation/ways-to-move`);
      await waitForLab(p);
      await p.waitForFunction(() => navigator.serviceWorker.controller !== null, null, { timeout: 30_000 });
      server.setRoot(b);
      await p.evaluate(() => navigator.serviceWorker.getRegistration().then((r) => r.update()));
      await banner(p);
      // Until the learner agrees, a reload still runs release A, whole.
      await p.reload();
      assert.equal(await waitForLab(p), "automation/ways-to-move");
      assert.equal(await release(p), "A");
      await banner(p);
      await Promise.all([p.waitForEvent("load"), p.click("#kinolab-update-reload")]);
      assert.equal(await waitForLab(p), "automation/ways-to-move");
      assert.equal(await release(p), "B");
      const wasm = await p.evaluate(() => performance.getEntriesByType("resource").map((e) => e.name).filter((n) => n.endsWith(".wasm")));
      assert.ok(wasm.length > 0 && wasm.every((n) => n.includes("kinolab-lab-b0b0b0b0")), JSON.stringify(wasm));
      const caches = await p.evaluate(() => caches.keys());
      const version = /const VERSION = "([0-9a-f]+)"/.exec(await readFile(`${b}/sw.js`, "utf8"))[1];
      assert.deepEqual(caches, [`kinolab-${version}`]);
    } finally {
      server.setRoot(dist);
      await context.close();
    }
  });

  await check("no console errors, page errors or failed loads", async () => {
    assert.deepEqual(problems, []);
  });
} finally {
  await browser.close();
  await server.close();
}
console.log(`e2e: ${passed} passed, ${failed} failed`);
process.exit(failed === 0 ? 0 : 1);
