//! The lesson folder on disk, and the pack format written from it (see
//! `pack.rs`). Shared by `build.rs`, which embeds the Markdown in native
//! builds, and the `pack-lessons` tool, which writes the web lab's pack.

use std::path::{Path, PathBuf};

/// Every Markdown and PNG file under `root`: its path relative to `root`
/// (with `/`) and on disk, sorted by the relative path.
pub fn lesson_files(root: &Path) -> Vec<(String, PathBuf)> {
    let mut found = Vec::new();
    collect(root, &mut found);
    let mut files: Vec<(String, PathBuf)> = found
        .into_iter()
        .filter_map(|path| {
            let relative = path.strip_prefix(root).ok()?;
            let relative = relative.to_string_lossy().replace('\\', "/");
            (relative.ends_with(".md") || relative.ends_with(".png")).then_some((relative, path))
        })
        .collect();
    files.sort();
    files
}

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

/// Files as a pack: each path, a zero byte, its length as a little-endian
/// `u32` and its bytes, the whole at zlib's best compression. `None` when
/// a file is larger than 4 GiB.
pub fn pack<'a>(files: impl IntoIterator<Item = (&'a str, &'a [u8])>) -> Option<Vec<u8>> {
    let mut raw = Vec::new();
    for (path, body) in files {
        raw.extend_from_slice(path.as_bytes());
        raw.push(0);
        raw.extend_from_slice(&u32::try_from(body.len()).ok()?.to_le_bytes());
        raw.extend_from_slice(body);
    }
    Some(miniz_oxide::deflate::compress_to_vec_zlib(&raw, 10))
}
