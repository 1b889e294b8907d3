// Writes the release's version and file list into the built service worker.
//
// usage: node web/stamp-sw.mjs [DIR]   (Trunk runs it after each build with
// TRUNK_STAGING_DIR set; DIR defaults to that, then to dist)
// VERSION is a hash of the names of the lab's script and wasm, which carry
// their content's hash (Trunk's filehash), and of the content of the files
// fetched beside them (the lessons and fonts), so any change to the lab
// makes a new version. PRECACHE lists the page, every file it loads, the
// manifest and the icons: the lab, whole, for offline use.
import { readdir, readFile, writeFile } from "node:fs/promises";
import { join } from "node:path";
import { createHash } from "node:crypto";

const dir = process.argv[2] ?? process.env.TRUNK_STAGING_DIR ?? "dist";
const names = (await readdir(dir)).sort();
const lab = names.filter((n) => /^kinolab-lab-.*\.(js|wasm)$/.test(n));
if (lab.length === 0) throw new Error(`stamp-sw: no kinolab-lab script or wasm in ${dir}`);
const beside = names.filter((n) => /\.(pack|ttf)$/.test(n));
const hash = createHash("sha256").update(lab.join("\n"));
for (const n of beside) hash.update(await readFile(join(dir, n)));
const version = hash.digest("hex").slice(0, 16);
const shell = names.filter((n) => /\.(webmanifest|png)$/.test(n) || n === "index.html");
const precache = ["./", ...shell.map((n) => `./${n}`), ...lab.map((n) => `./${n}`), ...beside.map((n) => `./${n}`)];
const path = join(dir, "sw.js");
const source = await readFile(path, "utf8");
const stamped = source
  .replace(/^const VERSION = .*;$/m, `const VERSION = ${JSON.stringify(version)};`)
  .replace(/^const PRECACHE = .*;$/m, `const PRECACHE = ${JSON.stringify(precache)};`);
if (stamped === source && !source.includes(version)) throw new Error("stamp-sw: sw.js has no VERSION or PRECACHE line");
await writeFile(path, stamped);
console.log(`stamp-sw: ${path} is release ${version} (${precache.length} files)`);
