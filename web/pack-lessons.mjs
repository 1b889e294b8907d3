// Packs the lessons into one file the web lab fetches beside its wasm
// (the wasm leaves them out, so the lab downloads and compiles sooner).
// The format is the one crates/teach/lessons/src/pack.rs reads and its
// build.rs writes for native builds: in a zlib stream, each Markdown or PNG
// file under lessons/, sorted by path: the path, a zero byte, the length as
// a little-endian u32, the bytes.
//
// usage: node web/pack-lessons.mjs [DIR]   (Trunk runs it before each build
// with TRUNK_STAGING_DIR set; DIR defaults to that, then to dist)
import { readdir, readFile, writeFile, mkdir } from "node:fs/promises";
import { join, relative, sep } from "node:path";
import { deflateSync, constants } from "node:zlib";

const root = new URL("../lessons/", import.meta.url).pathname;
const dir = process.argv[2] ?? process.env.TRUNK_STAGING_DIR ?? "dist";

async function files(folder) {
  const found = [];
  for (const entry of await readdir(folder, { withFileTypes: true })) {
    const path = join(folder, entry.name);
    if (entry.isDirectory()) found.push(...(await files(path)));
    else if (/\.(md|png)$/.test(entry.name)) found.push(relative(root, path).split(sep).join("/"));
  }
  return found;
}

// Sorted by UTF-8 bytes, as Rust sorts the build's paths.
const paths = (await files(root)).sort((a, b) => Buffer.compare(Buffer.from(a), Buffer.from(b)));
const parts = [];
for (const path of paths) {
  const body = await readFile(join(root, path));
  const length = Buffer.alloc(4);
  length.writeUInt32LE(body.length);
  parts.push(Buffer.from(path), Buffer.from([0]), length, body);
}
const packed = deflateSync(Buffer.concat(parts), { level: constants.Z_BEST_COMPRESSION });
await mkdir(dir, { recursive: true });
await writeFile(join(dir, "lessons.pack"), packed);
console.log(`pack-lessons: ${paths.length} files, ${packed.length} bytes in ${join(dir, "lessons.pack")}`);
