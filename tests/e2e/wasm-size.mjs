// Where a wasm file's bytes go: code by crate (from the name section) and
// data. Reads the unoptimised build (which keeps function names); wasm-opt
// shrinks every crate, so the shares are what matters.
import { readFile } from "node:fs/promises";

function reader(bytes) {
  let at = 0;
  const r = {
    get at() { return at; },
    set at(v) { at = v; },
    byte: () => bytes[at++],
    u32() {
      let result = 0, shift = 0;
      for (;;) {
        const b = bytes[at++];
        result += (b & 0x7f) * 2 ** shift;
        if ((b & 0x80) === 0) return result;
        shift += 7;
      }
    },
    name() {
      const len = r.u32();
      const s = new TextDecoder().decode(bytes.subarray(at, at + len));
      at += len;
      return s;
    },
  };
  return r;
}

function limits(r) {
  const flags = r.byte();
  r.u32();
  if (flags & 1) r.u32();
}

/** The crate a mangled Rust symbol belongs to (legacy mangling), or "other". */
export function crateOf(symbol) {
  const m = /^_ZN(\d+)(.*)$/.exec(symbol);
  if (!m) return symbol.startsWith("__wbg") || symbol.startsWith("__wbindgen") ? "wasm-bindgen glue" : "other";
  const first = m[2].slice(0, Number(m[1]));
  // `<alloc::vec::Vec<T> as core::...>` is written `_$LT$alloc..vec..`.
  const inner = first.replace(/^_?\$LT\$/, "").replace(/^(\$RF\$|mut\$u20\$|dyn\$u20\$)+/, "");
  return inner.split("..")[0].split("$")[0] || "other";
}

/** Code bytes by crate, and data bytes, of the wasm at `path`. */
export async function sizeByCrate(path) {
  const bytes = new Uint8Array(await readFile(path));
  const r = reader(bytes);
  r.at = 8;
  let imported = 0;
  const bodies = [];
  const names = new Map();
  let data = 0;
  while (r.at < bytes.length) {
    const id = r.byte();
    const size = r.u32();
    const end = r.at + size;
    if (id === 2) {
      for (let n = r.u32(); n > 0; n--) {
        r.name(); r.name();
        const kind = r.byte();
        if (kind === 0) { r.u32(); imported++; }
        else if (kind === 1) { r.byte(); limits(r); }
        else if (kind === 2) limits(r);
        else if (kind === 3) { r.byte(); r.byte(); }
        else r.u32();
      }
    } else if (id === 10) {
      for (let n = r.u32(); n > 0; n--) {
        const len = r.u32();
        bodies.push(len);
        r.at += len;
      }
    } else if (id === 11) {
      data += size;
    } else if (id === 0) {
      if (r.name() === "name") {
        while (r.at < end) {
          const sub = r.byte();
          const subEnd = r.u32() + r.at;
          if (sub === 1) for (let n = r.u32(); n > 0; n--) { const index = r.u32(); names.set(index, r.name()); }
          r.at = subEnd;
        }
      }
    }
    r.at = end;
  }
  const byCrate = new Map();
  bodies.forEach((len, i) => {
    const crate = crateOf(names.get(i + imported) ?? "");
    byCrate.set(crate, (byCrate.get(crate) ?? 0) + len);
  });
  const code = bodies.reduce((a, b) => a + b, 0);
  return { code, data, byCrate: [...byCrate].sort((a, b) => b[1] - a[1]) };
}
