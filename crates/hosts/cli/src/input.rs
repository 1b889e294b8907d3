//! Reading the files a command is given, within bounds.
//!
//! Every file goes through [`read`]: only regular files (a FIFO with no
//! writer would block forever, `/dev/zero` never ends), at most
//! [`MAX_FILE_BYTES`], and valid UTF-8, each refusal in one line naming
//! the file and the bound.

use std::fs::File;
use std::io::Read;
use std::path::Path;

use crate::Failure;

/// The largest file any command reads: far above any robot, model, run or
/// world file a person writes.
pub(crate) const MAX_FILE_BYTES: u64 = 4 * 1024 * 1024;

/// The text of a regular file of at most [`MAX_FILE_BYTES`].
pub(crate) fn read(path: &Path) -> Result<String, Failure> {
    let name = path.display().to_string();
    String::from_utf8(bytes(path)?).map_err(|e| {
        Failure(format!(
            "{name}: not UTF-8 text (bad byte at offset {})",
            e.utf8_error().valid_up_to()
        ))
    })
}

/// A learner's script: like [`read`], but text saved in another encoding
/// is read with its bad bytes replaced (and a notice saying how many)
/// rather than refused, as an editor would open it.
pub(crate) fn read_script(path: &Path) -> Result<(String, Option<String>), Failure> {
    let bytes = bytes(path)?;
    if bytes.contains(&0) {
        return Err(Failure(format!(
            "{}: not a text file (it holds NUL bytes)",
            path.display()
        )));
    }
    match String::from_utf8(bytes) {
        Ok(text) => Ok((text, None)),
        Err(e) => {
            let bytes = e.into_bytes();
            let text = String::from_utf8_lossy(&bytes).into_owned();
            let bad = text.matches('\u{fffd}').count();
            let notice = format!(
                "{}: not UTF-8 text; read with {bad} unreadable byte{} shown as \u{fffd} (save the file as UTF-8)",
                path.display(),
                if bad == 1 { "" } else { "s" }
            );
            Ok((text, Some(notice)))
        }
    }
}

/// The bytes of a regular file of at most [`MAX_FILE_BYTES`].
fn bytes(path: &Path) -> Result<Vec<u8>, Failure> {
    let name = path.display().to_string();
    let cannot = |e: std::io::Error| Failure(format!("{name}: cannot read: {e}"));
    let meta = std::fs::metadata(path).map_err(cannot)?;
    if !meta.is_file() {
        return Err(Failure(format!(
            "{name}: not a regular file (a folder, device or pipe cannot be read as input)"
        )));
    }
    if meta.len() > MAX_FILE_BYTES {
        return Err(too_big(&name));
    }
    let mut bytes = Vec::new();
    File::open(path)
        .and_then(|f| f.take(MAX_FILE_BYTES + 1).read_to_end(&mut bytes))
        .map_err(cannot)?;
    if bytes.len() as u64 > MAX_FILE_BYTES {
        return Err(too_big(&name));
    }
    Ok(bytes)
}

fn too_big(name: &str) -> Failure {
    Failure(format!(
        "{name}: larger than the input bound of {} MB",
        MAX_FILE_BYTES / (1024 * 1024)
    ))
}
