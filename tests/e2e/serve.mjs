// A tiny static file server for the built lab, on loopback only.
import { createServer } from "node:http";
import { readFile, stat } from "node:fs/promises";
import { extname, join, normalize } from "node:path";

const TYPES = {
  ".html": "text/html; charset=utf-8",
  ".js": "text/javascript",
  ".mjs": "text/javascript",
  ".wasm": "application/wasm",
  ".css": "text/css",
  ".png": "image/png",
  ".json": "application/json",
  ".webmanifest": "application/manifest+json",
};

/** Serve `root` on 127.0.0.1 at a free port; resolves to { url, setRoot, close }. */
export function serve(root) {
  // `setRoot` swaps the folder served, as a host does when a new release
  // is deployed.
  const server = createServer(async (req, res) => {
    const path = normalize(decodeURIComponent(new URL(req.url, "http://x").pathname)).replace(/^(\.\.[/\\])+/, "");
    let file = join(root, path);
    try {
      if ((await stat(file)).isDirectory()) file = join(file, "index.html");
      const headers = { "content-type": TYPES[extname(file)] ?? "application/octet-stream", "cache-control": "no-cache", "vary": "accept-encoding" };
      // Like a host that serves precompressed files: the Brotli or gzip copy
      // beside the file (`cargo xtask dist` writes them), when the browser
      // accepts it.
      const accepts = req.headers["accept-encoding"] ?? "";
      let body = null;
      for (const [encoding, suffix] of [["br", ".br"], ["gzip", ".gz"]]) {
        if (body === null && accepts.includes(encoding)) {
          body = await readFile(file + suffix).catch(() => null);
          if (body !== null) headers["content-encoding"] = encoding;
        }
      }
      body ??= await readFile(file);
      res.writeHead(200, headers);
      res.end(body);
    } catch {
      res.writeHead(404, { "content-type": "text/plain" });
      res.end("not found");
    }
  });
  return new Promise((resolve) => {
    server.listen(0, "127.0.0.1", () => {
      const { port } = server.address();
      resolve({
        url: `http://127.0.0.1:${port}/`,
        setRoot: (folder) => { root = folder; },
        close: () => new Promise((r) => server.close(r)),
      });
    });
  });
}

/** Launch Debian's headless Chromium with the flags this machine needs. */
export async function launch(extraArgs = []) {
  const { chromium } = await import("../../web/node_modules/playwright-core/index.mjs");
  return chromium.launch({
    executablePath: process.env.CHROMIUM ?? "/usr/bin/chromium",
    headless: true,
    args: [
      "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run",
      "--disable-background-networking", "--disable-component-update", "--disable-sync",
      "--use-gl=angle", "--use-angle=swiftshader", "--enable-unsafe-swiftshader",
      ...extraArgs,
    ],
  });
}

/** Wait until the lab has drawn its first frame; returns the page it shows. */
/// Wait until the lab shows the page at `address` (after a jump that only
/// changes the hash, the old page is still "ready" for a moment).
export async function waitForPage(page, address, timeout = 90_000) {
  await page.waitForFunction(
    (a) => document.documentElement.dataset.kinolabReady === "1" && document.documentElement.dataset.kinolabPage === a,
    address,
    { timeout },
  );
  return address;
}

export async function waitForLab(page, timeout = 90_000) {
  await page.waitForFunction(() => document.documentElement.dataset.kinolabReady === "1", null, { timeout });
  return page.evaluate(() => document.documentElement.dataset.kinolabPage);
}

// The points widgets publish on the page (a port of the component lab), in
// CSS pixels: canvas content has no elements to aim at.
export async function points(page) {
  const text = await page.evaluate(() => document.documentElement.dataset.kinolabPoints || "");
  return Object.fromEntries(text.trim().split("\n").filter(Boolean).map((line) => {
    const parts = line.split(" ");
    const y = Number(parts.pop());
    const x = Number(parts.pop());
    return [parts.join(" "), { x, y }];
  }));
}
