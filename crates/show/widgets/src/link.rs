//! Widget state in a link, one format for every widget.
//!
//! A link carries a widget's settings (the struct it reads from its
//! schema-checked parameters), the instant its player shows and the events
//! sprung while it ran: [`write`] puts them as the `key: value` lines a
//! lesson would write (plus `@t` and `@events`) in URL-safe base64 after
//! the version letter `b`, and [`read`] takes them back through the widget
//! schema, so a value out of range or of the wrong kind is refused with
//! the schema's own message. Nothing here panics on any text.
//!
//! Links made before settings were typed (version `a`: a widget's own
//! struct in postcard) still open: [`decode`] reads them.

use base64::Engine as _;
use base64::engine::general_purpose::URL_SAFE_NO_PAD;
use serde::Serialize;
use serde::de::DeserializeOwned;

/// The first format's version (postcard of a widget's own struct).
const VERSION: char = 'a';
/// The settings format's version.
const SETTINGS: char = 'b';

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

/// What a link carries beyond the settings: the instant the player shows
/// (s) and the events sprung while the run went, each at its time.
#[derive(Debug, Clone, PartialEq)]
pub struct Moment<E> {
    pub instant: f64,
    pub events: Vec<(f64, E)>,
}

impl<E> Default for Moment<E> {
    fn default() -> Self {
        Self {
            instant: 0.0,
            events: Vec::new(),
        }
    }
}

/// `settings` of the widget `widget`, with `moment`, as link text; `None`
/// while they are what the lesson set up (`initial`) and nothing has run.
pub fn write<T: Serialize + PartialEq, E: Serialize>(
    widget: &str,
    settings: &T,
    initial: &T,
    moment: &Moment<E>,
) -> Option<String> {
    if settings == initial && moment.instant == 0.0 && moment.events.is_empty() {
        return None;
    }
    let params = kinolab_schema::settings::to_params(widget, settings).ok()?;
    let events = match moment.events.is_empty() {
        true => None,
        false => Some(serde_json::to_string(&moment.events).ok()?),
    };
    write_lines(&params, moment.instant, events.as_deref())
}

/// The part of [`write`] that does not depend on the widget's types (kept
/// out of the generic function so the lab's wasm holds it once).
fn write_lines(params: &[(String, String)], instant: f64, events: Option<&str>) -> Option<String> {
    let mut lines = String::new();
    for (key, value) in params {
        lines += &format!("{key}: {value}\n");
    }
    if instant != 0.0 {
        lines += &format!("@t: {instant}\n");
    }
    if let Some(events) = events {
        lines += &format!("@events: {events}\n");
    }
    if lines.is_empty() {
        // Every setting at the schema's default: say so, since a link with
        // no lines at all is one cut short (see [`is_bare`]).
        lines += "@t: 0\n";
    }
    let mut text = String::from(SETTINGS);
    URL_SAFE_NO_PAD.encode_string(lines.as_bytes(), &mut text);
    (text.len() <= MAX_LEN).then_some(text)
}

/// Link text back into settings and a moment, checked by the widget
/// schema; the error says in a line what was wrong.
pub fn read<T: DeserializeOwned, E: DeserializeOwned>(
    widget: &str,
    text: &str,
) -> Result<(T, Moment<E>), String> {
    let (params, instant, events) = read_lines(widget, text)?;
    let events = match events {
        Some(json) => {
            serde_json::from_str(&json).map_err(|_| "its events are damaged".to_owned())?
        }
        None => Vec::new(),
    };
    Ok((params.settings()?, Moment { instant, events }))
}

/// The part of [`read`] that does not depend on the widget's types: the
/// checked parameters, the instant, and the events as JSON text.
fn read_lines(
    widget: &str,
    text: &str,
) -> Result<(kinolab_schema::Params, f64, Option<String>), String> {
    if text.len() > MAX_LEN {
        return Err(format!("it is longer than {MAX_LEN} characters"));
    }
    let body = text
        .strip_prefix(SETTINGS)
        .ok_or("it is not a widget state this lab can read")?;
    let bytes = URL_SAFE_NO_PAD
        .decode(body)
        .map_err(|_| "it is damaged (cut short or altered)".to_owned())?;
    let lines = String::from_utf8(bytes).map_err(|_| "it is damaged (not text)".to_owned())?;
    if lines.trim().is_empty() {
        return Err("it is empty (cut short)".into());
    }
    let mut params = Vec::new();
    let (mut instant_at, mut events) = (0.0, None);
    for line in lines.lines() {
        let (key, value) = line
            .split_once(": ")
            .ok_or_else(|| format!("`{line}` is not a setting"))?;
        match key {
            "@t" => instant_at = instant(value)?,
            "@events" => events = Some(value.to_owned()),
            _ => params.push((key.to_owned(), value.to_owned())),
        }
    }
    let spec = kinolab_lessons::WidgetSpec {
        name: widget.to_owned(),
        params,
        line: 0,
    };
    Ok((kinolab_schema::validate(&spec)?, instant_at, events))
}

/// Whether `text` is a settings link with nothing in it: a link cut
/// short, since [`write`] always writes a line. (It would [`read`] as the
/// schema's defaults.)
pub fn is_bare(text: &str) -> bool {
    text.strip_prefix(SETTINGS).is_some_and(str::is_empty)
}

/// Whether `settings` of the widget `widget` are within its schema (for
/// settings that did not come through [`read`], such as an old link's).
pub fn check<T: Serialize>(widget: &str, settings: &T) -> Result<(), String> {
    let params = kinolab_schema::settings::to_params(widget, settings)?;
    let spec = kinolab_lessons::WidgetSpec {
        name: widget.to_owned(),
        params,
        line: 0,
    };
    kinolab_schema::validate(&spec).map(|_| ())
}

/// An instant: a time from 0 to an hour.
fn instant(text: &str) -> Result<f64, String> {
    match text.trim().parse::<f64>() {
        Ok(t) if (0.0..=3600.0).contains(&t) => Ok(t),
        _ => Err(format!(
            "its instant `{text}` is not a time from 0 to 3600 s"
        )),
    }
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

    /// The leg-events widget's settings.
    #[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
    struct Legs {
        legs: u32,
    }

    #[test]
    fn settings_and_the_moment_round_trip_through_the_schema() {
        let initial = Legs { legs: 2 };
        let none: Moment<String> = Moment::default();
        assert_eq!(write("leg-events", &initial, &initial, &none), None);
        let moment = Moment {
            instant: 12.4,
            events: vec![(3.25, "door".to_owned()), (7.0, "person".to_owned())],
        };
        let text = write("leg-events", &Legs { legs: 6 }, &initial, &moment).unwrap_or_default();
        assert!(text.starts_with('b'), "{text}");
        let (back, m): (Legs, Moment<String>) =
            read("leg-events", &text).unwrap_or_else(|e| panic!("{e}"));
        assert_eq!((back, m), (Legs { legs: 6 }, moment));
    }

    #[test]
    fn damaged_settings_say_what_is_wrong() {
        let encode = |lines: &str| format!("b{}", URL_SAFE_NO_PAD.encode(lines));
        let read_legs = |text: &str| read::<Legs, String>("leg-events", text).map(|(s, _)| s);
        let e = read_legs(&encode("legs: 99\n")).unwrap_err();
        assert_eq!(
            e,
            "parameter `legs` must be a whole number from 1 to 12, found `99`"
        );
        let e = read_legs(&encode("legs: 4\ncolour: red\n")).unwrap_err();
        assert!(e.contains("has no parameter `colour`"), "{e}");
        let e = read_legs(&encode("legs: 4\n@t: 1e308\n")).unwrap_err();
        assert!(e.contains("instant"), "{e}");
        let e = read_legs(&encode("legs: 4\n@events: [[1, \n")).unwrap_err();
        assert!(e.contains("events"), "{e}");
        let text = encode("legs: 4\n");
        assert!(read_legs(&text[..text.len() - 2]).is_err(), "cut short");
        assert!(read_legs("a!!!").is_err());
        assert!(read_legs(&format!("b{}", "A".repeat(MAX_LEN))).is_err());
        assert!(read_legs(&encode("")).is_err(), "nothing at all");
        assert_eq!(
            read_legs(&encode("@t: 0\n")),
            Ok(Legs { legs: 2 }),
            "the schema's default"
        );
        // Settings back at the schema's defaults still make a link.
        let back = write(
            "leg-events",
            &Legs { legs: 2 },
            &Legs { legs: 4 },
            &Moment::<()>::default(),
        )
        .unwrap_or_default();
        assert_eq!(read_legs(&back), Ok(Legs { legs: 2 }));
        assert!(is_bare(&encode("")));
    }

    #[test]
    fn a_link_back_to_the_defaults_is_not_bare() {
        let moment: Moment<String> = Moment::default();
        let text =
            write("leg-events", &Legs { legs: 2 }, &Legs { legs: 6 }, &moment).unwrap_or_default();
        assert!(!is_bare(&text), "{text}");
        let (back, m): (Legs, Moment<String>) =
            read("leg-events", &text).unwrap_or_else(|e| panic!("{e}"));
        assert_eq!((back, m), (Legs { legs: 2 }, moment));
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
