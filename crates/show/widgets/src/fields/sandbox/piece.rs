//! One primitive as the learner edits it: every number kept, whatever the
//! kind, so switching kind and back loses nothing. The core checks it.

use egui::{ComboBox, DragValue, Slider};
use kinolab_fields::FieldError;
use kinolab_fields::file::{Entry, Kind as EntryKind, ProfileName};
use kinolab_fields::primitive::{Primitive, Profile, Sense, Source, Spin};
use serde::{Deserialize, Serialize};

#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
pub(super) enum Kind {
    Uniform,
    Attractive,
    Repulsive,
    Tangential,
    Perpendicular,
}

impl Kind {
    pub const ALL: [Kind; 5] = [
        Kind::Uniform,
        Kind::Attractive,
        Kind::Repulsive,
        Kind::Tangential,
        Kind::Perpendicular,
    ];

    pub fn name(self) -> &'static str {
        match self {
            Kind::Uniform => "uniform",
            Kind::Attractive => "attractive",
            Kind::Repulsive => "repulsive",
            Kind::Tangential => "tangential",
            Kind::Perpendicular => "perpendicular",
        }
    }

    /// The profiles the reference sheet allows for this kind.
    fn profiles(self) -> &'static [ProfileKind] {
        use ProfileKind::*;
        match self {
            Kind::Uniform => &[Constant],
            Kind::Attractive => &[Constant, Linear, Potential],
            Kind::Repulsive => &[Constant, Linear, Exponential, Potential],
            Kind::Tangential | Kind::Perpendicular => &[Constant, Linear, Exponential],
        }
    }
}

#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
pub(super) enum ProfileKind {
    Constant,
    Linear,
    Exponential,
    Potential,
}

impl ProfileKind {
    fn name(self) -> &'static str {
        match self {
            ProfileKind::Constant => "constant",
            ProfileKind::Linear => "linear",
            ProfileKind::Exponential => "exponential",
            ProfileKind::Potential => "potential",
        }
    }
}

/// An editable primitive.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub(super) struct Piece {
    pub kind: Kind,
    pub profile: ProfileKind,
    /// The centre, or the segment's start.
    pub at: [f64; 2],
    /// The segment's end.
    pub to: [f64; 2],
    pub radius: f64,
    pub gain: f64,
    pub range: f64,
    /// Whether an attractive field reaches everywhere (no range).
    pub unlimited: bool,
    pub lambda: f64,
    pub direction_deg: f64,
    /// Tangential: clockwise; perpendicular: pulls towards the segment.
    pub flipped: bool,
}

impl Piece {
    /// A new piece of `kind` at `at`, with numbers that show it well.
    pub fn new(kind: Kind, at: [f64; 2]) -> Self {
        let profile = match kind {
            Kind::Uniform => ProfileKind::Constant,
            _ => ProfileKind::Linear,
        };
        Self {
            kind,
            profile,
            at,
            to: [at[0], at[1] + 1.5],
            radius: if matches!(kind, Kind::Repulsive | Kind::Tangential) {
                0.3
            } else {
                0.0
            },
            gain: 1.0,
            range: 1.0,
            unlimited: false,
            lambda: 0.4,
            direction_deg: 0.0,
            flipped: false,
        }
    }

    /// Whether this piece reaches everywhere (no range).
    fn unranged(&self) -> bool {
        self.kind == Kind::Uniform
            || (self.kind == Kind::Attractive
                && self.unlimited
                && self.profile != ProfileKind::Linear)
    }

    /// The piece as a field file's entry (every number as it is here).
    pub fn entry(&self) -> Entry {
        let profile = match self.profile {
            ProfileKind::Constant => ProfileName::Constant,
            ProfileKind::Linear => ProfileName::Linear,
            ProfileKind::Exponential => ProfileName::Exponential,
            ProfileKind::Potential => ProfileName::Potential,
        };
        let mut e = Entry {
            gain: Some(self.gain),
            profile: Some(profile),
            range: (!self.unranged()).then_some(self.range),
            lambda: (self.profile == ProfileKind::Exponential).then_some(self.lambda),
            ..Entry::default()
        };
        let centre = |e: &mut Entry| {
            e.x = Some(self.at[0]);
            e.y = Some(self.at[1]);
        };
        match self.kind {
            Kind::Uniform => {
                e.kind = Some(EntryKind::Uniform);
                e.direction_deg = Some(self.direction_deg);
            }
            Kind::Attractive => {
                e.kind = Some(EntryKind::Attractive);
                centre(&mut e);
            }
            Kind::Repulsive | Kind::Tangential => {
                e.kind = Some(if self.kind == Kind::Repulsive {
                    EntryKind::Repulsive
                } else {
                    EntryKind::Tangential
                });
                centre(&mut e);
                e.radius = Some(self.radius);
                if self.kind == Kind::Tangential {
                    e.spin = Some(if self.flipped { Spin::Cw } else { Spin::Ccw });
                }
            }
            Kind::Perpendicular => {
                e.kind = Some(EntryKind::Perpendicular);
                e.from = Some(self.at);
                e.to = Some(self.to);
                e.sense = Some(if self.flipped {
                    Sense::Toward
                } else {
                    Sense::Away
                });
            }
        }
        e
    }

    /// The piece that edits the entry `e` (checked by the core; a uniform
    /// field keeps its direction in degrees exactly as written).
    pub fn from_entry(e: &Entry) -> Result<Self, FieldError> {
        let mut piece = Piece::from_primitive(&e.primitive()?);
        if let Some(d) = e.direction_deg {
            piece.direction_deg = d;
        }
        Ok(piece)
    }

    /// The piece that edits `p`.
    pub fn from_primitive(p: &Primitive) -> Self {
        let mut piece = Piece::new(Kind::Attractive, [0.0, 0.0]);
        piece.gain = p.gain;
        piece.range = p.range.unwrap_or(1.0);
        piece.unlimited = p.range.is_none();
        piece.profile = match p.profile {
            Profile::Constant => ProfileKind::Constant,
            Profile::Linear => ProfileKind::Linear,
            Profile::Exponential { lambda } => {
                piece.lambda = lambda;
                ProfileKind::Exponential
            }
            Profile::Potential => ProfileKind::Potential,
        };
        match p.source {
            Source::Uniform { direction } => {
                piece.kind = Kind::Uniform;
                piece.direction_deg = direction.to_degrees();
            }
            Source::Attractive { centre } => piece.at = [centre.x, centre.y],
            Source::Repulsive { centre, radius } => {
                piece.kind = Kind::Repulsive;
                piece.at = [centre.x, centre.y];
                piece.radius = radius;
            }
            Source::Tangential {
                centre,
                radius,
                spin,
            } => {
                piece.kind = Kind::Tangential;
                piece.at = [centre.x, centre.y];
                piece.radius = radius;
                piece.flipped = spin == Spin::Cw;
            }
            Source::Perpendicular { from, to, sense } => {
                piece.kind = Kind::Perpendicular;
                piece.at = [from.x, from.y];
                piece.to = [to.x, to.y];
                piece.flipped = sense == Sense::Toward;
            }
        }
        piece
    }

    /// A one-line description for the list.
    pub fn title(&self) -> String {
        match self.kind {
            Kind::Uniform => format!(
                "uniform towards {}°",
                kinolab_common::display::fixed(self.direction_deg, 0)
            ),
            k => format!("{} · {}", k.name(), self.profile.name()),
        }
    }

    /// The editor for this piece; returns whether anything changed. `locked`
    /// leaves only range and gain free (an exercise's wall).
    pub fn editor(&mut self, ui: &mut egui::Ui, locked: bool) -> bool {
        let before = *self;
        if !locked {
            ComboBox::from_label("kind")
                .selected_text(self.kind.name())
                .show_ui(ui, |ui| {
                    for k in Kind::ALL {
                        crate::widget::choose(ui, &mut self.kind, k, k.name());
                    }
                });
            if !self.kind.profiles().contains(&self.profile) {
                self.profile = self.kind.profiles()[0];
            }
            ComboBox::from_label("profile")
                .selected_text(self.profile.name())
                .show_ui(ui, |ui| {
                    for p in self.kind.profiles() {
                        crate::widget::choose(ui, &mut self.profile, *p, p.name());
                    }
                });
        }
        ui.add(Slider::new(&mut self.gain, 0.0..=5.0).text("gain m"));
        let ranged = self.kind != Kind::Uniform;
        if ranged && self.kind == Kind::Attractive && self.profile != ProfileKind::Linear && !locked
        {
            ui.checkbox(&mut self.unlimited, "reaches everywhere (no range)");
        }
        let has_range = ranged
            && !(self.kind == Kind::Attractive
                && self.unlimited
                && self.profile != ProfileKind::Linear);
        if has_range {
            ui.add(Slider::new(&mut self.range, 0.05..=5.0).text("range D (m)"));
        }
        if !locked {
            self.shape_editor(ui);
        }
        *self != before
    }

    fn shape_editor(&mut self, ui: &mut egui::Ui) {
        if self.profile == ProfileKind::Exponential {
            ui.add(Slider::new(&mut self.lambda, 0.05..=3.0).text("decay λ (m)"));
        }
        match self.kind {
            Kind::Uniform => {
                ui.add(Slider::new(&mut self.direction_deg, -180.0..=180.0).text("direction (°)"));
            }
            Kind::Repulsive | Kind::Tangential => {
                ui.add(Slider::new(&mut self.radius, 0.0..=2.0).text("radius ρ (m)"));
            }
            _ => {}
        }
        match self.kind {
            Kind::Tangential => {
                ui.horizontal(|ui| {
                    ui.radio_value(&mut self.flipped, false, "counter-clockwise");
                    ui.radio_value(&mut self.flipped, true, "clockwise");
                });
            }
            Kind::Perpendicular => {
                ui.horizontal(|ui| {
                    ui.radio_value(&mut self.flipped, false, "pushes away");
                    ui.radio_value(&mut self.flipped, true, "pulls toward");
                });
            }
            _ => {}
        }
        ui.horizontal(|ui| {
            ui.label("at");
            ui.add(
                DragValue::new(&mut self.at[0])
                    .speed(0.02)
                    .max_decimals(2)
                    .prefix("x "),
            );
            ui.add(
                DragValue::new(&mut self.at[1])
                    .speed(0.02)
                    .max_decimals(2)
                    .prefix("y "),
            );
        });
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn pieces_round_trip_through_the_core() {
        let field = kinolab_fields::catalogue::preset("goal-behind-a-rock")
            .unwrap()
            .field()
            .unwrap();
        for p in &field.primitives {
            let piece = Piece::from_primitive(p);
            assert_eq!(piece.entry().primitive().unwrap(), *p);
        }
        for k in Kind::ALL {
            let piece = Piece::new(k, [1.0, 1.0]);
            // As an entry and back: a primitive, the same entry.
            let entry = piece.entry();
            assert!(entry.primitive().is_ok(), "{}", k.name());
            let back = Piece::from_entry(&entry).unwrap();
            assert_eq!(back.entry(), entry, "{}", k.name());
        }
        let mut uniform = Piece::new(Kind::Uniform, [0.0, 0.0]);
        uniform.direction_deg = 37.3;
        let back = Piece::from_entry(&uniform.entry()).unwrap();
        assert_eq!(back.direction_deg, 37.3);
    }
}
