//! With the `embedded` feature, pack every Markdown and PNG file under the
//! workspace's `lessons/` folder into the build (see `src/pack.rs` for the
//! format). Markdown compresses threefold; images go in as they are.

use std::path::PathBuf;

#[path = "src/folder.rs"]
mod folder;

fn main() {
    if std::env::var_os("CARGO_FEATURE_EMBEDDED").is_none() {
        return;
    }
    let manifest = PathBuf::from(std::env::var("CARGO_MANIFEST_DIR").unwrap_or_default());
    let out_dir = PathBuf::from(std::env::var("OUT_DIR").unwrap_or_default());
    let root = manifest.join("../../../lessons");
    println!("cargo:rerun-if-changed={}", root.display());
    let mut bodies = Vec::new();
    for (relative, path) in folder::lesson_files(&root) {
        println!("cargo:rerun-if-changed={}", path.display());
        let body =
            std::fs::read(&path).unwrap_or_else(|e| panic!("cannot read {}: {e}", path.display()));
        bodies.push((relative, body));
    }
    let packed = folder::pack(bodies.iter().map(|(p, b)| (p.as_str(), b.as_slice())))
        .unwrap_or_else(|| panic!("a lesson file is larger than 4 GiB"));
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
