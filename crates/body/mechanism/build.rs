//! The real robots' URDF files under `robots/` go into the build deflated:
//! they are XML, about a sixth of their size once packed, and the lab's
//! wasm has a size budget.

use std::path::PathBuf;

fn main() {
    let manifest = PathBuf::from(std::env::var("CARGO_MANIFEST_DIR").unwrap_or_default());
    let out = PathBuf::from(std::env::var("OUT_DIR").unwrap_or_default());
    for name in ["ur5", "panda", "solo12"] {
        let path = manifest.join(format!("robots/{name}.urdf"));
        println!("cargo:rerun-if-changed={}", path.display());
        let text =
            std::fs::read(&path).unwrap_or_else(|e| panic!("cannot read {}: {e}", path.display()));
        let packed = miniz_oxide::deflate::compress_to_vec_zlib(&text, 10);
        let target = out.join(format!("{name}.urdf.zlib"));
        std::fs::write(&target, packed)
            .unwrap_or_else(|e| panic!("cannot write {}: {e}", target.display()));
    }
}
