// Precompressed copies of the built site, for hosts that serve them.
//
// usage: node web/precompress.mjs DIST_DIR
// Writes NAME.br (Brotli, best quality) and NAME.gz (gzip written by
// Zopfli, about 5 % smaller than zlib's level 9 and read by every gzip
// reader) beside every text or wasm file in DIST_DIR larger than 1 KiB,
// checks that each copy unpacks to the file, and prints the sizes. A host that serves precompressed files (nginx's gzip_static and
// brotli_static, Caddy's `precompressed`, most static hosts) sends the
// smaller copy to browsers that accept it; the others send the original.
import { readdir, readFile, writeFile } from "node:fs/promises";
import { join, extname } from "node:path";
import { brotliCompressSync, brotliDecompressSync, gunzipSync, constants } from "node:zlib";
import { gzipAsync } from "@gfx/zopfli";

const COMPRESSIBLE = new Set([".wasm", ".js", ".html", ".css", ".json", ".webmanifest", ".svg"]);
const dist = process.argv[2] ?? "dist";

async function* files(dir) {
  for (const entry of await readdir(dir, { withFileTypes: true })) {
    const path = join(dir, entry.name);
    if (entry.isDirectory()) yield* files(path);
    else if (COMPRESSIBLE.has(extname(entry.name))) yield path;
  }
}

const mb = (n) => (n / 1e6).toFixed(2);
for await (const path of files(dist)) {
  const raw = await readFile(path);
  if (raw.length < 1024) continue;
  const br = brotliCompressSync(raw, {
    params: {
      [constants.BROTLI_PARAM_QUALITY]: constants.BROTLI_MAX_QUALITY,
      [constants.BROTLI_PARAM_SIZE_HINT]: raw.length,
    },
  });
  // One pass of Zopfli's optimiser: more gain 0.2 % on the lab's wasm for
  // four times the time.
  const gz = Buffer.from(await gzipAsync(raw, { numiterations: 1 }));
  if (!brotliDecompressSync(br).equals(raw) || !gunzipSync(gz).equals(raw)) {
    throw new Error(`${path}: a compressed copy does not unpack to the file`);
  }
  await writeFile(`${path}.br`, br);
  await writeFile(`${path}.gz`, gz);
  if (raw.length > 100_000) {
    console.log(`${path}: ${mb(raw.length)} MB, Brotli ${mb(br.length)} MB, gzip ${mb(gz.length)} MB`);
  }
}

