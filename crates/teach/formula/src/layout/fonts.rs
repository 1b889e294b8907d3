//! The lab's fonts: egui's Ubuntu Light and Hack cut down to the
//! characters lessons and widgets draw (see `fonts/subset.py`), about a
//! quarter of the originals' size. Formulas are set against their metrics.
//!
//! Native builds embed them (the `embedded` feature); the web lab leaves
//! them out of its wasm and its page hands them over, fetched beside the
//! wasm, before the lab starts ([`provide`]).

use std::collections::BTreeMap;
use std::sync::{Arc, OnceLock};

use egui::{FontData, FontDefinitions, FontFamily};

/// The two faces: text, then code.
type Faces = [Arc<FontData>; 2];

static PROVIDED: OnceLock<Faces> = OnceLock::new();

/// Hand over the two font files the page fetched (`kinolab-sans.ttf`,
/// `kinolab-mono.ttf`); the first call wins.
pub fn provide(sans: Vec<u8>, mono: Vec<u8>) {
    let _ = PROVIDED.set([sans, mono].map(|bytes| face(FontData::from_owned(bytes))));
}

/// A face drawn from its outlines as they are, without hinting. The cut
/// fonts carry no hinting instructions, so egui would hint them with
/// skrifa's automatic hinter, which studies the whole font again each time
/// the text size changes: most of the cost of a first page's new glyphs.
/// Text is placed by the shaper's advances either way, so layout (and every
/// formula's metrics) is the same; only the glyphs' pixels differ.
fn face(data: FontData) -> Arc<FontData> {
    let tweak = egui::FontTweak {
        hinting: Some(false),
        ..Default::default()
    };
    Arc::new(data.tweak(tweak))
}

#[cfg(feature = "embedded")]
fn embedded() -> Option<&'static Faces> {
    const SANS: &[u8] = include_bytes!("../../fonts/kinolab-sans.ttf");
    const MONO: &[u8] = include_bytes!("../../fonts/kinolab-mono.ttf");
    static FACES: OnceLock<Faces> = OnceLock::new();
    Some(FACES.get_or_init(|| [SANS, MONO].map(|bytes| face(FontData::from_static(bytes)))))
}

#[cfg(not(feature = "embedded"))]
fn embedded() -> Option<&'static Faces> {
    None
}

/// Text in Ubuntu Light with Hack behind it for the symbols Ubuntu lacks
/// (∈ ∇ ⋅ → ‖ ⌊); code in Hack with Ubuntu behind it. Without fonts (a web
/// page that has not handed them over) egui's own definitions.
pub fn definitions() -> FontDefinitions {
    let Some([sans, mono]) = PROVIDED.get().or_else(embedded) else {
        return FontDefinitions::default();
    };
    let font_data = BTreeMap::from([
        ("kinolab-sans".to_owned(), sans.clone()),
        ("kinolab-mono".to_owned(), mono.clone()),
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
