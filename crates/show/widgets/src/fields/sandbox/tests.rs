use super::analysis::REMEDIES;
use super::*;
use crate::registry::{create, spec};

fn sandbox(params: &[(&str, &str)]) -> Sandbox {
    let p = kinolab_schema::validate(&spec(NAME, params)).unwrap_or_else(|e| panic!("{e}"));
    let mut s = Sandbox::new(p.settings().unwrap_or_else(|e| panic!("{e}")))
        .unwrap_or_else(|e| panic!("{e}"));
    s.settings.remedies = true;
    s
}

#[test]
fn the_analysis_finds_the_u_trap_and_the_remedies_run() {
    let mut s = sandbox(&[("preset", "u-shaped-wall")]);
    let field = s.field.clone().unwrap_or_else(|| panic!("no field"));
    s.analysis.update(
        &field,
        s.version,
        s.design.start,
        &s.area,
        false,
        true,
        true,
    );
    let traps: Vec<_> = s
        .analysis
        .minima(&field)
        .into_iter()
        .filter(|m| !m.goal)
        .collect();
    assert_eq!(traps.len(), 1);
    assert!((traps[0].x - 3.75).abs() < 1e-6);
    assert_eq!(s.analysis.remedies.len(), REMEDIES.len() + 1);
    assert!(s.analysis.trail.is_some());
}

#[test]
fn a_link_restores_the_design() {
    let mut s = sandbox(&[("preset", "rock-on-the-axis")]);
    s.design
        .pieces
        .push(Piece::new(piece::Kind::Tangential, [2.0, 0.0]));
    s.changed();
    let link = s.state().unwrap_or_default();
    let mut t = sandbox(&[("preset", "rock-on-the-axis")]);
    let _ = t.restore(&link);
    assert_eq!(t.design.entries(), s.design.entries());
    assert_eq!(t.preset_pieces, 2);
    assert!(t.restore("zzz").is_err());
    assert_eq!(
        t.design.entries(),
        s.design.entries(),
        "a damaged link changes nothing"
    );
}

#[test]
fn a_link_of_the_first_format_still_opens() {
    // preset, pieces, goal, start, streamlines, shading, unicycle,
    // remedies drawn, editable: made by the first format's own types.
    let field = preset("rock-on-the-axis")
        .and_then(|p| p.field().ok())
        .unwrap_or_else(|| panic!("no preset"));
    let mut pieces: Vec<Piece> = field.primitives.iter().map(Piece::from_primitive).collect();
    pieces[1].gain = 2.5;
    let old = (
        "rock-on-the-axis",
        pieces.clone(),
        Some([4.0_f64, 0.5_f64]),
        [0.0_f64, 0.25_f64],
        true,
        false,
        true,
        [false, true, false, false, true],
        true,
    );
    let text = link::encode(&old).unwrap_or_default();
    let mut s = sandbox(&[]);
    assert_eq!(s.restore(&text), Ok(()));
    assert_eq!(s.settings.preset, "rock-on-the-axis");
    assert_eq!(s.design.pieces[1].gain, 2.5);
    assert_eq!(s.design.start, [0.0, 0.25]);
    assert_eq!(s.settings.goal, Some([4.0, 0.5]));
    assert_eq!(s.settings.paths.as_deref(), Some("avoid-past, wavefront"));
    assert!((s.settings.unicycle, s.settings.shading) == (true, false));
    // A start off the map: refused, the lesson's settings kept.
    let bad = (
        "rock-on-the-axis",
        pieces,
        None::<[f64; 2]>,
        [0.0_f64, 1e9_f64],
        true,
        true,
        false,
        [false; 5],
        true,
    );
    let mut s = sandbox(&[("preset", "corridor")]);
    assert!(s.restore(&link::encode(&bad).unwrap_or_default()).is_err());
    assert_eq!(s.settings.preset, "corridor");
    assert!(create(&spec(NAME, &[])).is_ok());
}

#[test]
fn the_descent_is_played_and_saved_as_the_command_line_follows_it() {
    let mut s = sandbox(&[("start", "0.3, 0.4")]);
    s.seek(0.5);
    let run = s.saved_run().unwrap_or_else(|| panic!("no run"));
    assert_eq!(run.args[3], "0.3,0.4");
    let field = Field::from_json(&run.text).unwrap_or_else(|e| panic!("{e}"));
    let whole = descend(&field, Vec2::new(0.3, 0.4), STEPS).unwrap_or_else(|e| panic!("{e}"));
    let path = kinolab_common::display::tidy_report(&whole.path[..=50].to_vec())
        .unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(run.shows, vec![("/path".to_owned(), path)]);
    // The CSV has a row per point of the path.
    let csv = s.path_csv();
    assert_eq!(csv.lines().count(), whole.path.len() + 1);
    // At the end, the outcome too.
    s.seek(1000.0);
    let run = s.saved_run().unwrap_or_else(|| panic!("no run"));
    assert_eq!(run.shows.len(), 3);
    // The instant travels in the link.
    s.seek(0.25);
    let mut again = sandbox(&[]);
    assert_eq!(again.restore(&s.state().unwrap_or_default()), Ok(()));
    assert_eq!(again.saved_run(), s.saved_run());
}
