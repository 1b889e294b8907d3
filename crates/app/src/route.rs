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
        let path = hash
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
}
