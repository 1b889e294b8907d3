//! Widget state in a link, one format for every widget.
//!
//! A widget keeps what a link must carry in a serde struct; [`encode`]
//! writes it with postcard (serde's compact binary form) as URL-safe
//! base64 after a version letter, and [`decode`] reads it back. A damaged,
//! truncated or foreign state decodes to `None`, never to a panic, so a bad
//! link only means the widget starts as the lesson set it up.

use base64::Engine as _;
use base64::engine::general_purpose::URL_SAFE_NO_PAD;
use serde::Serialize;
use serde::de::DeserializeOwned;

/// The format's version; states of another version are ignored.
const VERSION: char = 'a';

/// The longest state a link may carry, in characters.
pub const MAX_LEN: usize = 8_000;

/// `state` as link text (letters, digits, `-` and `_` only).
pub fn encode<T: Serialize>(state: &T) -> Option<String> {
    let bytes = postcard::to_allocvec(state).ok()?;
    let mut text = String::with_capacity(1 + bytes.len() * 4 / 3 + 2);
    text.push(VERSION);
    URL_SAFE_NO_PAD.encode_string(bytes, &mut text);
    (text.len() <= MAX_LEN).then_some(text)
}

/// A widget's state for a link: `now` encoded, or `None` while it is
/// still what the lesson set up (`initial`).
pub fn changed<T: Serialize + PartialEq>(now: &T, initial: &T) -> Option<String> {
    (now != initial).then(|| encode(now)).flatten()
}

/// Link text back into a state; `None` for anything that is not a state
/// of this type and version.
pub fn decode<T: DeserializeOwned>(text: &str) -> Option<T> {
    if text.len() > MAX_LEN {
        return None;
    }
    let body = text.strip_prefix(VERSION)?;
    let bytes = URL_SAFE_NO_PAD.decode(body).ok()?;
    let (state, rest) = postcard::take_from_bytes::<T>(&bytes).ok()?;
    rest.is_empty().then_some(state)
}

#[cfg(test)]
mod tests {
    use super::*;
    use serde::Deserialize;

    #[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
    struct State {
        tab: u8,
        gains: [f64; 3],
        plan: String,
        marks: Vec<bool>,
    }

    fn sample() -> State {
        State {
            tab: 2,
            gains: [3.0, 8.0, -1.5],
            plan: "line 1; arc 0.5 90".into(),
            marks: vec![true, false, true],
        }
    }

    #[test]
    fn states_round_trip_as_url_safe_text() {
        let text = encode(&sample()).unwrap_or_default();
        assert!(
            text.chars()
                .all(|c| c.is_ascii_alphanumeric() || c == '-' || c == '_'),
            "{text}"
        );
        assert_eq!(decode::<State>(&text), Some(sample()));
    }

    #[test]
    fn damaged_states_decode_to_nothing() {
        let text = encode(&sample()).unwrap_or_default();
        assert_eq!(decode::<State>(""), None);
        assert_eq!(decode::<State>("zzz"), None, "unknown version");
        assert_eq!(decode::<State>(&text[..text.len() - 3]), None, "truncated");
        assert_eq!(
            decode::<State>(&format!("{text}AA")),
            None,
            "trailing bytes"
        );
        assert_eq!(decode::<State>("a!!!"), None, "not base64");
        assert_eq!(decode::<[f64; 3]>(&text), None, "another type");
        assert_eq!(decode::<State>(&"a".repeat(MAX_LEN + 1)), None, "too long");
    }
}
