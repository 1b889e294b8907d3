//! Pages and their addresses in the URL hash.
//!
//! `#/automation/open-and-closed-worlds` opens that lesson; `#/gallery`
//! the widget gallery and `#/gallery/<widget>` one widget alone; an empty
//! hash (or `#/`) is the home page. `#dev` only tells the page shell to
//! skip the offline cache and is otherwise the home page too.

/// What the main area shows.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Page {
    Home,
    /// A lesson by its `unit/lesson` address.
    Lesson(String),
    /// Every widget, or one by name.
    Gallery(Option<String>),
}

impl Page {
    /// Read a URL hash (with or without the leading `#`).
    pub fn from_hash(hash: &str) -> Page {
        let path = hash.split_once('?').map_or(hash, |(path, _)| path);
        let path = path
            .trim_start_matches('#')
            .trim_start_matches("dev")
            .trim_matches('/');
        if path == "gallery" {
            return Page::Gallery(None);
        }
        if let Some(widget) = path.strip_prefix("gallery/")
            && !widget.is_empty()
            && !widget.contains('/')
        {
            return Page::Gallery(Some(widget.to_owned()));
        }
        match path.split_once('/') {
            Some((unit, lesson))
                if !unit.is_empty() && !lesson.is_empty() && !lesson.contains('/') =>
            {
                Page::Lesson(format!("{unit}/{lesson}"))
            }
            _ => Page::Home,
        }
    }

    /// The URL hash for this page, `#/unit/lesson` or `#/`.
    pub fn hash(&self) -> String {
        match self {
            Page::Home => "#/".to_owned(),
            Page::Gallery(_) | Page::Lesson(_) => format!("#/{}", self.address()),
        }
    }

    /// The page's address without `#/`: `unit/lesson`, `gallery`,
    /// `gallery/<widget>`, or empty for the home page.
    pub fn address(&self) -> String {
        match self {
            Page::Home => String::new(),
            Page::Lesson(address) => address.clone(),
            Page::Gallery(None) => "gallery".to_owned(),
            Page::Gallery(Some(name)) => format!("gallery/{name}"),
        }
    }
}

/// Widget states carried after `?` in a lesson's hash:
/// `#/unit/lesson?w0=<state>&w2=<state>` gives `[(0, state), (2, state)]`.
pub fn widget_states(hash: &str) -> Vec<(usize, String)> {
    let Some((_, query)) = hash.split_once('?') else {
        return Vec::new();
    };
    query
        .split('&')
        .filter_map(|pair| {
            let (key, value) = pair.split_once('=')?;
            let n = key.strip_prefix('w')?.parse().ok()?;
            Some((n, value.replace("%20", " ")))
        })
        .collect()
}

/// The hash for a lesson with its widgets' states.
pub fn lesson_hash(address: &str, states: &[(usize, String)]) -> String {
    let mut hash = format!("#/{address}");
    for (i, (n, state)) in states.iter().enumerate() {
        hash.push(if i == 0 { '?' } else { '&' });
        hash.push_str(&format!("w{n}={state}"));
    }
    hash
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn hashes_round_trip() {
        let page = Page::Lesson("automation/ways-to-move".into());
        assert_eq!(page.hash(), "#/automation/ways-to-move");
        assert_eq!(Page::from_hash(&page.hash()), page);
        assert_eq!(Page::from_hash("#/automation/ways-to-move/"), page);
        assert_eq!(Page::from_hash(""), Page::Home);
        assert_eq!(Page::from_hash("#dev"), Page::Home);
        assert_eq!(Page::from_hash("#/"), Page::Home);
        assert_eq!(Page::from_hash("#/automation"), Page::Home);
        assert_eq!(Page::from_hash("#/a/b/c"), Page::Home);
        assert_eq!(Page::from_hash("#/gallery"), Page::Gallery(None));
        let one = Page::Gallery(Some("dh-link".into()));
        assert_eq!(Page::from_hash(&one.hash()), one);
        assert_eq!(one.hash(), "#/gallery/dh-link");
    }

    use proptest::prelude::*;

    /// Pieces damaged addresses are made of: real ones, cut and altered.
    fn address() -> impl Strategy<Value = String> {
        let piece = prop::sample::select(vec![
            "#",
            "/",
            "?",
            "&",
            "=",
            "w0",
            "w99999999999999999999",
            "gallery",
            "automation",
            "ways-to-move",
            "..",
            "%2F",
            "%",
            "\u{0}",
            "é→",
            "#dev",
            " ",
            "bAAAA",
            "a",
        ]);
        (
            prop::collection::vec(piece, 0..12),
            prop::collection::vec(any::<char>(), 0..20),
        )
            .prop_map(|(pieces, noise)| {
                let mut s: String = pieces.concat();
                s.extend(noise);
                s
            })
    }

    proptest! {
        /// Any address lands on a page, and the page's own address lands
        /// on it again; widget states are read without panicking.
        #[test]
        fn any_address_lands_on_a_page(hash in address()) {
            let page = Page::from_hash(&hash);
            prop_assert_eq!(Page::from_hash(&page.hash()), page.clone());
            let states = widget_states(&hash);
            if let Page::Lesson(a) = &page {
                let again = lesson_hash(a, &states);
                prop_assert_eq!(widget_states(&again), states);
            }
        }
    }

    #[test]
    fn a_huge_address_is_read_in_bounded_time() {
        let hash = format!("#/{}?{}", "a/".repeat(100_000), "w1=x&".repeat(100_000));
        assert_eq!(Page::from_hash(&hash), Page::Home);
        assert!(widget_states(&hash).len() <= 100_000);
    }

    #[test]
    fn widget_states_ride_after_the_question_mark() {
        let hash = "#/wheeled/kinds?w0=f,90,0,0.25,0.1;c,180,0,0.3,0.05,d=0.04&w2=x";
        assert_eq!(Page::from_hash(hash), Page::Lesson("wheeled/kinds".into()));
        let states = widget_states(hash);
        assert_eq!(
            states,
            vec![
                (0, "f,90,0,0.25,0.1;c,180,0,0.3,0.05,d=0.04".to_owned()),
                (2, "x".to_owned())
            ]
        );
        assert_eq!(lesson_hash("wheeled/kinds", &states), hash);
        assert!(widget_states("#/a/b?junk&wx=1").is_empty());
    }
}
