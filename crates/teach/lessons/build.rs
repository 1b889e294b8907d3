//! With the `embedded` feature, pack every file under the workspace's
//! `lessons/` folder into the build (see `src/pack.rs` for the format;
//! `web/pack-lessons.mjs` writes the same file for the web page). Markdown
//! compresses threefold; images go in as they are.

use std::path::{Path, PathBuf};

fn collect(dir: &Path, out: &mut Vec<PathBuf>) {
    let Ok(entries) = std::fs::read_dir(dir) else {
        return;
    };
    for entry in entries.flatten() {
        let path = entry.path();
        if path.is_dir() {
            collect(&path, out);
        } else {
            out.push(path);
        }
    }
}

fn main() {
    if std::env::var_os("CARGO_FEATURE_EMBEDDED").is_none() {
        return;
    }
    let manifest = PathBuf::from(std::env::var("CARGO_MANIFEST_DIR").unwrap_or_default());
    let out_dir = PathBuf::from(std::env::var("OUT_DIR").unwrap_or_default());
    let root = manifest.join("../../../lessons");
    println!("cargo:rerun-if-changed={}", root.display());
    let mut paths = Vec::new();
    collect(&root, &mut paths);
    paths.sort();
    let mut raw = Vec::new();
    for path in &paths {
        println!("cargo:rerun-if-changed={}", path.display());
        let Ok(relative) = path.strip_prefix(&root) else {
            continue;
        };
        let relative = relative.to_string_lossy().replace('\\', "/");
        if !(relative.ends_with(".md") || relative.ends_with(".png")) {
            continue;
        }
        let body =
            std::fs::read(path).unwrap_or_else(|e| panic!("cannot read {}: {e}", path.display()));
        raw.extend_from_slice(relative.as_bytes());
        raw.push(0);
        let length =
            u32::try_from(body.len()).unwrap_or_else(|_| panic!("{relative} is too large"));
        raw.extend_from_slice(&length.to_le_bytes());
        raw.extend_from_slice(&body);
    }
    let packed = miniz_oxide::deflate::compress_to_vec_zlib(&raw, 10);
    let pack_path = out_dir.join("lessons.pack");
    if let Err(e) = std::fs::write(&pack_path, packed) {
        panic!("cannot write {}: {e}", pack_path.display());
    }
    let code = format!(
        "pub static PACKED: &[u8] = include_bytes!({:?});\n",
        pack_path.display().to_string()
    );
    let out = out_dir.join("bundled_lessons.rs");
    if let Err(e) = std::fs::write(&out, code) {
        panic!("cannot write {}: {e}", out.display());
    }
}
