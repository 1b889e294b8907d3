//! The progress file: everything the lab keeps about a learner (lessons
//! opened, quiz answers, the code and widget states they left), as one
//! download to take to another computer and load there.

use serde::{Deserialize, Serialize};

use super::{Millis, Progress, migrate};

/// The name the download gets.
pub const FILE_NAME: &str = "kinolab-progress.json";

/// What the file says it is, so that any other JSON is refused.
const KIND: &str = "kinolab-progress";

/// The largest file read: far above a whole course's progress (tens of
/// kilobytes), far below what would stall the tab.
const LARGEST: usize = 8 << 20;

#[derive(Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
struct ProgressFile {
    kind: String,
    /// When the file was saved.
    saved_at: Millis,
    progress: serde_json::Value,
}

/// The file's text for `progress`, saved at `at`.
pub fn write(progress: &Progress, at: Millis) -> String {
    let file = ProgressFile {
        kind: KIND.to_owned(),
        saved_at: at,
        progress: serde_json::to_value(progress).unwrap_or_default(),
    };
    serde_json::to_string_pretty(&file).unwrap_or_default()
}

/// The progress in a file's bytes; a damaged or foreign file is refused
/// with a sentence saying why.
pub fn read(bytes: &[u8]) -> Result<Progress, String> {
    if bytes.len() > LARGEST {
        return Err(format!(
            "it is {:.1} MB, far larger than any progress file",
            bytes.len() as f64 / 1e6
        ));
    }
    let text = std::str::from_utf8(bytes).map_err(|_| "it is not a text file".to_owned())?;
    let value: serde_json::Value =
        serde_json::from_str(text).map_err(|e| format!("it is damaged ({e})"))?;
    if value.get("kind").and_then(|k| k.as_str()) != Some(KIND) {
        return Err("it is not a Kinolab progress file".to_owned());
    }
    let file: ProgressFile =
        serde_json::from_value(value).map_err(|e| format!("it is damaged ({e})"))?;
    migrate::read_value(file.progress).map_err(|why| format!("its progress: {why}"))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn sample() -> Progress {
        let mut p = Progress::default();
        p.visited.insert("behaviours/emergence".into());
        p.record_answer("behaviours/emergence#0", true, 5);
        p.keep_widget("behaviours/emergence@w1", Some("seed=4"), 6);
        p
    }

    #[test]
    fn a_saved_file_loads_back_the_same() {
        let text = write(&sample(), 7);
        assert!(text.contains("\"kind\": \"kinolab-progress\""));
        assert_eq!(read(text.as_bytes()), Ok(sample()));
    }

    #[test]
    fn a_file_of_an_earlier_format_is_migrated() {
        let v1 = include_str!("fixtures/v1.json");
        let text = format!(r#"{{"kind":"kinolab-progress","saved_at":1,"progress":{v1}}}"#);
        let p = read(text.as_bytes()).unwrap();
        assert!(p.visited.contains("legged-locomotion/legs-and-wheels"));
    }

    #[test]
    fn damaged_and_foreign_files_say_why() {
        let said = |bytes: &[u8]| read(bytes).unwrap_err();
        let good = write(&sample(), 7);
        assert!(said(&good.as_bytes()[..good.len() / 2]).starts_with("it is damaged"));
        assert_eq!(
            said(b"{\"version\":2}"),
            "it is not a Kinolab progress file"
        );
        assert_eq!(said(&[0xff, 0xfe, 0x00]), "it is not a text file");
        assert!(said(&vec![b' '; LARGEST + 1]).contains("far larger"));
        let wrong = good.replace("\"attempts\": 1", "\"attempts\": -1");
        assert!(said(wrong.as_bytes()).starts_with("its progress: format 2"));
        let extra = good.replace("\"saved_at\"", "\"owner\": 1, \"saved_at\"");
        assert!(said(extra.as_bytes()).contains("unknown field `owner`"));
    }
}
