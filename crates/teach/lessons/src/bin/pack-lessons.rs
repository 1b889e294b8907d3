//! Writes the web lab's `lessons.pack`: the lesson folder's images and its
//! course prepared (every lesson parsed and checked here, so a lesson that
//! does not parse stops the site's build with where and why).
//!
//! usage: pack-lessons [DIR]   (Trunk runs it before each build with
//! TRUNK_STAGING_DIR set; DIR defaults to that, then to `dist`)

use std::io::Write as _;
use std::path::PathBuf;
use std::process::ExitCode;

fn main() -> ExitCode {
    let dir = std::env::args()
        .nth(1)
        .or_else(|| std::env::var("TRUNK_STAGING_DIR").ok())
        .map_or_else(|| PathBuf::from("dist"), PathBuf::from);
    let root = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../../lessons");
    let packed = match kinolab_lessons::web_pack(&root) {
        Ok(packed) => packed,
        Err(e) => {
            eprintln!("pack-lessons: {e}");
            return ExitCode::FAILURE;
        }
    };
    let out = dir.join("lessons.pack");
    let written = std::fs::create_dir_all(&dir).and_then(|()| std::fs::write(&out, &packed));
    if let Err(e) = written {
        eprintln!("pack-lessons: cannot write {}: {e}", out.display());
        return ExitCode::FAILURE;
    }
    let said = writeln!(
        std::io::stdout(),
        "pack-lessons: {} bytes in {}",
        packed.len(),
        out.display()
    );
    ExitCode::from(u8::from(said.is_err()))
}
