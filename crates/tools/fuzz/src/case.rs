//! A case: the arguments of one `kinolab` call and the files it reads.

use std::path::{Path, PathBuf};

use serde::{Deserialize, Serialize};

/// What a case's folder holds under one name.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum FileSpec {
    /// A file with this text.
    Text(String),
    /// A file with these bytes (not UTF-8), as hexadecimal.
    Hex(String),
    /// `count` copies of `text`: large inputs without large case files.
    Repeat { text: String, count: usize },
    /// A named pipe that nobody writes to.
    Fifo,
    /// A folder.
    Folder,
}

/// Where the answer goes.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Sink {
    /// A file, read back and checked.
    #[default]
    File,
    /// `/dev/full`: every write fails with "no space left".
    Full,
    /// A pipe whose reader has gone.
    Closed,
}

/// What a regression case must also show, beyond the contract.
#[derive(Debug, Clone, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Expect {
    /// The exit status.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub exit: Option<i32>,
    /// Pieces the error line must contain.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub stderr_contains: Vec<String>,
    /// Pieces the error line must not contain.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub stderr_lacks: Vec<String>,
    /// Pieces the answer must contain.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub stdout_contains: Vec<String>,
}

/// One call of the command.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Case {
    /// The command it exercises (the table's row).
    pub command: String,
    /// The arguments after `kinolab`.
    pub args: Vec<String>,
    /// Files written into the case's folder before the call.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub files: Vec<(String, FileSpec)>,
    #[serde(default, skip_serializing_if = "is_default")]
    pub sink: Sink,
    /// Why the case exists (regression files say what once went wrong).
    #[serde(default, skip_serializing_if = "String::is_empty")]
    pub note: String,
    #[serde(default, skip_serializing_if = "is_default")]
    pub expect: Expect,
}

fn is_default<T: Default + PartialEq>(v: &T) -> bool {
    *v == T::default()
}

impl Case {
    pub fn new(command: &str, args: Vec<String>) -> Self {
        Self {
            command: command.to_owned(),
            args,
            files: Vec::new(),
            sink: Sink::File,
            note: String::new(),
            expect: Expect::default(),
        }
    }

    /// The same case with a file added.
    pub fn with_file(mut self, name: &str, spec: FileSpec) -> Self {
        self.files.push((name.to_owned(), spec));
        self
    }

    /// Write the case's files into `folder`.
    pub fn materialise(&self, folder: &Path) -> std::io::Result<()> {
        for (name, spec) in &self.files {
            let path = folder.join(name);
            if let Some(parent) = path.parent() {
                std::fs::create_dir_all(parent)?;
            }
            match spec {
                FileSpec::Text(t) => std::fs::write(&path, t)?,
                FileSpec::Hex(h) => std::fs::write(&path, from_hex(h))?,
                FileSpec::Repeat { text, count } => {
                    std::fs::write(&path, text.repeat((*count).min(1 << 26)))?
                }
                FileSpec::Folder => std::fs::create_dir_all(&path)?,
                FileSpec::Fifo => make_fifo(&path)?,
            }
        }
        Ok(())
    }
}

fn make_fifo(path: &Path) -> std::io::Result<()> {
    let status = std::process::Command::new("mkfifo").arg(path).status()?;
    if status.success() {
        Ok(())
    } else {
        Err(std::io::Error::other("mkfifo failed"))
    }
}

/// Bytes as hexadecimal.
pub fn to_hex(bytes: &[u8]) -> String {
    bytes.iter().map(|b| format!("{b:02x}")).collect()
}

fn from_hex(text: &str) -> Vec<u8> {
    (0..text.len() / 2)
        .filter_map(|i| u8::from_str_radix(text.get(2 * i..2 * i + 2)?, 16).ok())
        .collect()
}

/// Every `*.json` case in `folder`, sorted by name, with its path.
pub fn load_folder(folder: &Path) -> Result<Vec<(PathBuf, Case)>, String> {
    let mut paths: Vec<PathBuf> = std::fs::read_dir(folder)
        .map_err(|e| format!("{}: {e}", folder.display()))?
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.extension().is_some_and(|x| x == "json"))
        .collect();
    paths.sort();
    paths
        .into_iter()
        .map(|p| {
            let text = std::fs::read_to_string(&p).map_err(|e| format!("{}: {e}", p.display()))?;
            let case = serde_json::from_str(&text).map_err(|e| format!("{}: {e}", p.display()))?;
            Ok((p, case))
        })
        .collect()
}

/// Save `case` into `folder` under a name made from its content, so the
/// same failure is kept once.
pub fn save(folder: &Path, case: &Case) -> std::io::Result<PathBuf> {
    let text = serde_json::to_string_pretty(case).map_err(std::io::Error::other)?;
    let id = kinolab_common::random::hash(0x5eed, text.len() as u64, fnv(&text));
    let path = folder.join(format!("{}-{id:016x}.json", case.command));
    std::fs::create_dir_all(folder)?;
    std::fs::write(&path, text + "\n")?;
    Ok(path)
}

fn fnv(text: &str) -> u64 {
    text.bytes().fold(0xcbf2_9ce4_8422_2325, |h, b| {
        (h ^ u64::from(b)).wrapping_mul(0x100_0000_01b3)
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn cases_round_trip_through_json() {
        let case = Case::new("fk", vec!["fk".into(), "m.json".into()])
            .with_file("m.json", FileSpec::Hex(to_hex(&[0xff, 0x00, 0x7b])))
            .with_file(
                "big.json",
                FileSpec::Repeat {
                    text: "[".into(),
                    count: 3,
                },
            );
        let text = serde_json::to_string(&case).unwrap();
        let back: Case = serde_json::from_str(&text).unwrap();
        assert_eq!(back, case);
        assert_eq!(from_hex("ff007b"), vec![0xff, 0x00, 0x7b]);
    }
}
