//! Pages and their addresses in the URL hash.
//!
//! `#/automation/open-and-closed-worlds` opens that lesson; an empty hash
//! (or `#/`) is the home page. `#dev` only tells the page shell to skip the
//! offline cache and is otherwise the home page too.

/// What the main area shows.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Page {
    Home,
    /// A lesson by its `unit/lesson` address.
    Lesson(String),
}

impl Page {
    /// Read a URL hash (with or without the leading `#`).
    pub fn from_hash(hash: &str) -> Page {
        let path = hash.split_once('?').map_or(hash, |(path, _)| path);
        let path = path
            .trim_start_matches('#')
            .trim_start_matches("dev")
            .trim_matches('/');
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
            Page::Lesson(address) => format!("#/{address}"),
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
