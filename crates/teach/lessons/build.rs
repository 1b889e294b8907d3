//! Embed every lesson file under the workspace's `lessons/` folder, so the
//! lab needs no server to load them. The Markdown goes in as one
//! deflate-compressed blob (lesson text is about a tenth of the lab's
//! download, and compresses threefold); images go in as they are (PNG is
//! compressed already).

use std::fmt::Write as _;
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
    let manifest = PathBuf::from(std::env::var("CARGO_MANIFEST_DIR").unwrap_or_default());
    let out_dir = PathBuf::from(std::env::var("OUT_DIR").unwrap_or_default());
    let root = manifest.join("../../../lessons");
    println!("cargo:rerun-if-changed={}", root.display());
    let mut paths = Vec::new();
    collect(&root, &mut paths);
    paths.sort();
    let mut blob = String::new();
    let mut markdown = String::from("pub static MARKDOWN: &[(&str, usize, usize)] = &[\n");
    let mut images = String::from("pub static IMAGES: &[(&str, &[u8])] = &[\n");
    for path in &paths {
        println!("cargo:rerun-if-changed={}", path.display());
        let Ok(relative) = path.strip_prefix(&root) else {
            continue;
        };
        let relative = relative.to_string_lossy().replace('\\', "/");
        match path.extension().and_then(|e| e.to_str()) {
            Some("md") => {
                let text = std::fs::read_to_string(path)
                    .unwrap_or_else(|e| panic!("cannot read {}: {e}", path.display()));
                let _ = writeln!(
                    markdown,
                    "    ({relative:?}, {}, {}),",
                    blob.len(),
                    text.len()
                );
                blob.push_str(&text);
            }
            Some("png") => {
                let absolute = path.canonicalize().unwrap_or_else(|_| path.clone());
                let _ = writeln!(
                    images,
                    "    ({relative:?}, include_bytes!({:?})),",
                    absolute.display().to_string()
                );
            }
            _ => {}
        }
    }
    markdown.push_str("];\n");
    images.push_str("];\n");
    let packed = miniz_oxide::deflate::compress_to_vec_zlib(blob.as_bytes(), 10);
    let blob_path = out_dir.join("lessons.md.zlib");
    if let Err(e) = std::fs::write(&blob_path, packed) {
        panic!("cannot write {}: {e}", blob_path.display());
    }
    let code = format!(
        "{markdown}{images}pub static PACKED: &[u8] = include_bytes!({:?});\npub const UNPACKED_LEN: usize = {};\n",
        blob_path.display().to_string(),
        blob.len()
    );
    let out = out_dir.join("bundled_lessons.rs");
    if let Err(e) = std::fs::write(&out, code) {
        panic!("cannot write {}: {e}", out.display());
    }
}
