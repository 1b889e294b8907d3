//! Running the binary on a case: a fresh folder, no input, the answer into
//! a file (or `/dev/full`, or a closed pipe), a memory limit and a time
//! limit.

use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

use wait_timeout::ChildExt;

use crate::case::{Case, Sink};
use crate::contract::Outcome;

/// How a case is run.
#[derive(Debug, Clone)]
pub struct Limits {
    /// Killed (and called a hang) after this long.
    pub time: Duration,
    /// Address-space limit, KiB (`ulimit -v`).
    pub memory_kib: u64,
}

impl Default for Limits {
    fn default() -> Self {
        Self {
            time: Duration::from_secs(10),
            memory_kib: 2 * 1024 * 1024,
        }
    }
}

/// Run `binary` on `case` inside `folder` (created, then removed).
pub fn run(binary: &Path, case: &Case, folder: &Path, limits: &Limits) -> std::io::Result<Outcome> {
    let _ = std::fs::remove_dir_all(folder);
    std::fs::create_dir_all(folder)?;
    case.materialise(folder)?;
    let out_path = folder.join(".stdout");
    let err_path = folder.join(".stderr");
    let stdout = match case.sink {
        Sink::File => Stdio::from(std::fs::File::create(&out_path)?),
        Sink::Full => Stdio::from(std::fs::OpenOptions::new().write(true).open("/dev/full")?),
        Sink::Closed => Stdio::piped(),
    };
    // The shell sets the limits, then becomes the binary.
    let script = format!("ulimit -v {}; exec \"$0\" \"$@\"", limits.memory_kib);
    let started = Instant::now();
    let mut child = Command::new("sh")
        .arg("-c")
        .arg(script)
        .arg(binary)
        .args(&case.args)
        .current_dir(folder)
        .env("RUST_BACKTRACE", "0")
        .stdin(Stdio::null())
        .stdout(stdout)
        .stderr(Stdio::from(std::fs::File::create(&err_path)?))
        .spawn()?;
    // A closed pipe: the reader goes away at once.
    drop(child.stdout.take());
    let status = match child.wait_timeout(limits.time)? {
        Some(status) => Some(status),
        None => {
            let _ = child.kill();
            let _ = child.wait();
            None
        }
    };
    let elapsed = started.elapsed();
    let outcome = Outcome {
        status: status.and_then(|s| s.code()),
        stdout: read_capped(&out_path),
        stderr: read_capped(&err_path),
        elapsed,
        timed_out: status.is_none(),
    };
    let _ = std::fs::remove_dir_all(folder);
    Ok(outcome)
}

/// At most 40 MB of a file (more than the command may ever print).
fn read_capped(path: &Path) -> Vec<u8> {
    use std::io::Read;
    let mut bytes = Vec::new();
    if let Ok(f) = std::fs::File::open(path) {
        let _ = f.take(40 << 20).read_to_end(&mut bytes);
    }
    bytes
}

/// A scratch folder of its own for each caller, under the system's
/// temporary folder (campaigns may run side by side in one process).
pub fn scratch() -> PathBuf {
    static NEXT: std::sync::atomic::AtomicUsize = std::sync::atomic::AtomicUsize::new(0);
    let n = NEXT.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
    std::env::temp_dir().join(format!("kinolab-fuzz-{}-{n}", std::process::id()))
}
