//! Embed every lesson file (Markdown and PNG) under the workspace's
//! `lessons/` folder, so the lab needs no server to load them.

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
    let root = manifest.join("../../lessons");
    println!("cargo:rerun-if-changed={}", root.display());
    let mut paths = Vec::new();
    collect(&root, &mut paths);
    paths.sort();
    let mut markdown = String::from("pub static MARKDOWN: &[(&str, &str)] = &[\n");
    let mut images = String::from("pub static IMAGES: &[(&str, &[u8])] = &[\n");
    for path in &paths {
        println!("cargo:rerun-if-changed={}", path.display());
        let Ok(relative) = path.strip_prefix(&root) else {
            continue;
        };
        let relative = relative.to_string_lossy().replace('\\', "/");
        let absolute = path.canonicalize().unwrap_or_else(|_| path.clone());
        let target = match path.extension().and_then(|e| e.to_str()) {
            Some("md") => &mut markdown,
            Some("png") => &mut images,
            _ => continue,
        };
        let include = if target.starts_with("pub static MARKDOWN") {
            "include_str"
        } else {
            "include_bytes"
        };
        let _ = writeln!(
            target,
            "    ({relative:?}, {include}!({:?})),",
            absolute.display().to_string()
        );
    }
    markdown.push_str("];\n");
    images.push_str("];\n");
    let out =
        PathBuf::from(std::env::var("OUT_DIR").unwrap_or_default()).join("bundled_lessons.rs");
    if let Err(e) = std::fs::write(&out, markdown + &images) {
        panic!("cannot write {}: {e}", out.display());
    }
}
