//! The lab's fonts: egui's Ubuntu Light and Hack cut down to the
//! characters lessons and widgets draw (see `fonts/subset.py`), about a
//! quarter of the originals' size. Formulas are set against their metrics.

use std::collections::BTreeMap;
use std::sync::Arc;

use egui::{FontData, FontDefinitions, FontFamily};

const SANS: &[u8] = include_bytes!("../../fonts/kinolab-sans.ttf");
const MONO: &[u8] = include_bytes!("../../fonts/kinolab-mono.ttf");

/// Text in Ubuntu Light with Hack behind it for the symbols Ubuntu lacks
/// (∈ ∇ ⋅ → ‖ ⌊); code in Hack with Ubuntu behind it.
pub fn definitions() -> FontDefinitions {
    let font_data = BTreeMap::from([
        (
            "kinolab-sans".to_owned(),
            Arc::new(FontData::from_static(SANS)),
        ),
        (
            "kinolab-mono".to_owned(),
            Arc::new(FontData::from_static(MONO)),
        ),
    ]);
    let names = |list: [&str; 2]| list.map(str::to_owned).to_vec();
    let families = BTreeMap::from([
        (
            FontFamily::Proportional,
            names(["kinolab-sans", "kinolab-mono"]),
        ),
        (
            FontFamily::Monospace,
            names(["kinolab-mono", "kinolab-sans"]),
        ),
    ]);
    FontDefinitions {
        font_data,
        families,
    }
}
