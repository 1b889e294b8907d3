//! Static stability, hands on: drag the feet and the centre of mass of a
//! walker seen from above; click a foot to lift or lower it.

use egui::{Color32, Painter, Pos2, Rect, RichText, Sense, Stroke, vec2};
use kinolab_common::display::fixed;
use kinolab_locomotion::{Point, Stability, static_stability};
use serde::{Deserialize, Serialize};

use super::{draw_foot, draw_support};
use crate::draw::labels::Labels;
use crate::draw::{PlaneView, canvas, handle, marks};
use crate::export::{self, Export};
use crate::link::{self, Moment};
use crate::theme;
use crate::widget::{LabWidget, Params};

/// The widget's name in the schema.
const NAME: &str = "support-polygon";

/// Half-extent of the visible ground, metres (the schema's bounds).
const VIEW_HALF_WIDTH: f64 = 0.5;
const VIEW_HALF_HEIGHT: f64 = 0.32;

/// What the lesson sets and a link carries: the schema's parameters.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
struct Settings {
    legs: u32,
    /// Where each foot stands (spread around the body when `None`).
    feet: Option<Vec<Point>>,
    /// The feet off the ground, by number from 1 (`None`: none).
    lifted: Option<Vec<f64>>,
    com: Point,
}

/// The links of the first format: the feet and the centre of mass.
#[derive(Deserialize)]
struct Legacy {
    feet: Vec<LegacyFoot>,
    com: Point,
}

#[derive(Deserialize)]
struct LegacyFoot {
    at: Point,
    on_ground: bool,
}

impl Legacy {
    /// The same stance as settings (the schema checks the values).
    fn settings(self) -> Result<Settings, String> {
        let finite = self
            .feet
            .iter()
            .flat_map(|f| f.at)
            .chain(self.com)
            .all(f64::is_finite);
        if !finite {
            return Err("its feet are not all on the ground plane".into());
        }
        let lifted: Vec<f64> = (1..)
            .zip(&self.feet)
            .filter(|(_, f)| !f.on_ground)
            .map(|(n, _)| f64::from(n))
            .collect();
        Ok(Settings {
            legs: u32::try_from(self.feet.len()).map_err(|e| e.to_string())?,
            feet: Some(self.feet.iter().map(|f| f.at).collect()),
            lifted: (!lifted.is_empty()).then_some(lifted),
            com: self.com,
        })
    }
}

struct Foot {
    at: Point,
    on_ground: bool,
}

struct SupportPolygon {
    settings: Settings,
    initial: Settings,
}

pub fn create(p: &Params) -> Result<Box<dyn LabWidget>, String> {
    let settings: Settings = p.settings()?;
    Ok(Box::new(SupportPolygon {
        initial: settings.clone(),
        settings,
    }))
}

impl Settings {
    /// Feet spread evenly on an ellipse around the body, starting front-left.
    fn spread(legs: u32) -> Vec<Point> {
        (0..legs)
            .map(|i| {
                let angle = std::f64::consts::TAU * (f64::from(i) + 0.5) / f64::from(legs);
                [0.3 * angle.cos(), 0.2 * angle.sin()]
            })
            .collect()
    }

    /// Every foot, where it is and whether it stands.
    fn feet(&self) -> Vec<Foot> {
        let at = self.feet.clone().unwrap_or_else(|| Self::spread(self.legs));
        let lifted = self.lifted.as_deref().unwrap_or_default();
        (1..)
            .zip(at)
            .map(|(n, at)| Foot {
                at,
                on_ground: !lifted.contains(&f64::from(n)),
            })
            .collect()
    }

    /// Take the feet back (as the learner left them).
    fn set_feet(&mut self, feet: &[Foot]) {
        self.feet = Some(feet.iter().map(|f| f.at).collect());
        let lifted: Vec<f64> = (1..)
            .zip(feet)
            .filter(|(_, f)| !f.on_ground)
            .map(|(n, _)| f64::from(n))
            .collect();
        self.lifted = (!lifted.is_empty()).then_some(lifted);
    }

    /// Whether the stance is statically stable, and by how much (`None`
    /// with no foot down).
    fn verdict(&self) -> Option<Stability> {
        static_stability(self.com, &self.grounded()).ok()
    }

    fn grounded(&self) -> Vec<Point> {
        self.feet()
            .iter()
            .filter(|f| f.on_ground)
            .map(|f| f.at)
            .collect()
    }
}

fn clamp(p: Point) -> Point {
    [
        p[0].clamp(-VIEW_HALF_WIDTH, VIEW_HALF_WIDTH),
        p[1].clamp(-VIEW_HALF_HEIGHT, VIEW_HALF_HEIGHT),
    ]
}

/// A point moved by a screen displacement, kept on the visible ground.
fn moved(view: &PlaneView, p: Point, by: egui::Vec2) -> Point {
    let d = view.delta_to_world(by);
    clamp([p[0] + d[0], p[1] + d[1]])
}

impl SupportPolygon {
    /// The feet and the centre of mass as handles: drag to move, click a
    /// foot to lift or lower it.
    fn input(&mut self, ui: &mut egui::Ui, view: &PlaneView) {
        let base = ui.scope_id().with("feet");
        let mut feet = self.settings.feet();
        let mut moved_any = false;
        for (i, foot) in feet.iter_mut().enumerate() {
            let state = if foot.on_ground {
                "on the ground"
            } else {
                "lifted"
            };
            let label = format!("Foot {} ({state})", i + 1);
            let h = handle(ui, base.with(i), view.to_screen(foot.at), 12.0, &label);
            if h.dragged() {
                foot.at = moved(view, foot.at, h.moved);
                moved_any = true;
            } else if h.clicked() {
                foot.on_ground = !foot.on_ground;
                moved_any = true;
            }
        }
        if moved_any {
            self.settings.set_feet(&feet);
        }
        let com_at = view.to_screen(self.settings.com);
        let h = handle(
            ui,
            ui.scope_id().with("com"),
            com_at,
            12.0,
            "Centre of mass",
        );
        if h.dragged() {
            self.settings.com = moved(view, self.settings.com, h.moved);
        }
    }

    fn draw(
        &self,
        ui: &egui::Ui,
        painter: &Painter,
        view: &PlaneView,
        verdict: Option<&Stability>,
    ) {
        let ink = ui.visuals().text_color();
        let mut labels = Labels::default();
        if let Some(s) = verdict {
            let color = verdict_color(ui, s);
            draw_support(painter, &mut labels, view, s, self.settings.com, color);
        }
        let com = view.to_screen(self.settings.com);
        labels.reserve(Rect::from_center_size(com, vec2(20.0, 20.0)));
        self.draw_feet(painter, &mut labels, view, ink);
        draw_com(painter, com, theme::accent(ui));
        labels.draw(painter, &egui::FontId::proportional(theme::LABEL_SIZE));
    }

    fn draw_feet(&self, painter: &Painter, labels: &mut Labels, view: &PlaneView, ink: Color32) {
        for (i, foot) in self.settings.feet().iter().enumerate() {
            let out = egui::Vec2::new(foot.at[0] as f32, -foot.at[1] as f32);
            let at = view.to_screen(foot.at);
            let name = (i + 1).to_string();
            draw_foot(painter, labels, at, foot.on_ground, out, &name, ink);
        }
    }
}

fn draw_com(painter: &Painter, at: Pos2, color: Color32) {
    painter.circle(at, 8.0, color, Stroke::new(1.5, Color32::WHITE));
    marks::plus(painter, at, 5.0, Stroke::new(1.5, Color32::WHITE));
}

fn verdict_color(ui: &egui::Ui, s: &Stability) -> Color32 {
    if s.stable {
        theme::good_color(ui)
    } else {
        theme::error_color(ui)
    }
}

/// The verdict in words, the margin to the millimetre.
fn verdict_text(verdict: Option<&Stability>) -> String {
    let Some(s) = verdict else {
        return "No foot is on the ground: the walker falls.".into();
    };
    let cm = fixed(s.margin * 100.0, 1);
    if s.polygon.len() < 3 {
        "Not statically stable: the feet on the ground enclose no area.".into()
    } else if s.stable {
        format!("Statically stable: stability margin {cm} cm")
    } else if cm == "0.0" {
        "On the edge: the centre of mass lies on the polygon's border (margin 0).".into()
    } else {
        format!(
            "Tips over: the centre of mass is {} cm outside the support polygon",
            fixed(-s.margin * 100.0, 1)
        )
    }
}

impl LabWidget for SupportPolygon {
    /// How many feet are down, and the verdict with its margin.
    fn describe(&self) -> Option<String> {
        let feet = self.settings.feet();
        let down = feet.iter().filter(|f| f.on_ground).count();
        let verdict = verdict_text(self.settings.verdict().as_ref());
        Some(format!(
            "{down} of {} feet on the ground. {}.",
            feet.len(),
            verdict.trim_end_matches('.')
        ))
    }

    fn ui(&mut self, ui: &mut egui::Ui) {
        let width = ui.available_width().min(720.0);
        let (response, painter) = canvas(ui, vec2(width, 320.0), Sense::hover());
        let rect = response.rect;
        let view = PlaneView::fit(
            rect,
            [-VIEW_HALF_WIDTH, -VIEW_HALF_HEIGHT],
            [VIEW_HALF_WIDTH, VIEW_HALF_HEIGHT],
        );
        self.input(ui, &view);
        let verdict = self.settings.verdict();
        self.draw(ui, &painter, &view, verdict.as_ref());
        painter.text(
            rect.right_top() + vec2(-10.0, 10.0),
            egui::Align2::RIGHT_TOP,
            "seen from above, front to the right →",
            egui::FontId::proportional(theme::SMALL_SIZE),
            ui.visuals().weak_text_color(),
        );
        let color = verdict
            .as_ref()
            .map_or(theme::error_color(ui), |s| verdict_color(ui, s));
        ui.label(
            RichText::new(verdict_text(verdict.as_ref()))
                .strong()
                .color(color),
        );
        let feet = self.settings.feet();
        let lifted = feet.iter().filter(|f| !f.on_ground).count();
        ui.horizontal_wrapped(|ui| {
            ui.label(RichText::new(format!("{lifted} of {} feet lifted. Drag a foot or the blue centre of mass; click a foot to lift or lower it.", feet.len())).small());
            if ui.button("Reset stance").clicked() {
                self.settings = self.initial.clone();
            }
        });
        export::bar(
            ui,
            ui.scope_id().with("support-exports"),
            &[Export::Png {
                file: "kinolab-support-polygon.png",
                rect,
            }],
        );
    }

    fn state(&self) -> Option<String> {
        link::write(
            NAME,
            &self.settings,
            &self.initial,
            &Moment::<()>::default(),
        )
    }

    fn restore(&mut self, state: &str) -> Result<(), String> {
        let settings = match link::read::<Settings, ()>(NAME, state) {
            Ok((settings, _)) => settings,
            Err(why) => match link::decode::<Legacy>(state) {
                Some(old) => old.settings()?,
                None => return Err(why),
            },
        };
        // The old format's values pass through the schema too.
        link::check(NAME, &settings)?;
        self.settings = settings;
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_verdict_never_reads_minus_zero() {
        let square = [[-0.1, -0.1], [0.1, -0.1], [0.1, 0.1], [-0.1, 0.1]];
        let edge = static_stability([0.1 - 1e-17, 0.0], &square).ok();
        let text = verdict_text(edge.as_ref());
        assert!(!text.contains("-0.0"), "{text}");
        let inside = static_stability([0.0, 0.0], &square).ok();
        assert_eq!(
            verdict_text(inside.as_ref()),
            "Statically stable: stability margin 10.0 cm"
        );
        let outside = static_stability([0.15, 0.0], &square).ok();
        assert_eq!(
            verdict_text(outside.as_ref()),
            "Tips over: the centre of mass is 5.0 cm outside the support polygon"
        );
    }

    fn widget(params: &[(&str, &str)]) -> SupportPolygon {
        let spec = crate::registry::spec(NAME, params);
        let p = kinolab_schema::validate(&spec).unwrap_or_else(|e| panic!("{e}"));
        let settings: Settings = p.settings().unwrap_or_else(|e| panic!("{e}"));
        SupportPolygon {
            initial: settings.clone(),
            settings,
        }
    }

    #[test]
    fn the_description_holds_the_feet_down_and_the_margin() {
        let mut w = widget(&[("legs", "4")]);
        let margin = |w: &SupportPolygon| {
            let s = static_stability(w.settings.com, &w.settings.grounded());
            s.map_or(f64::NAN, |s| s.margin)
        };
        let words = w.describe().unwrap_or_default();
        assert!(words.starts_with("4 of 4 feet on the ground."), "{words}");
        let cm = fixed(margin(&w) * 100.0, 1);
        assert!(words.contains(&format!("margin {cm} cm")), "{words}");
        // The centre of mass moved off the body: the words follow.
        w.settings.com = [0.4, 0.0];
        let moved = w.describe().unwrap_or_default();
        let out = fixed(-margin(&w) * 100.0, 1);
        assert!(moved.contains(&format!("{out} cm outside")), "{moved}");
        let mut feet = w.settings.feet();
        feet[0].on_ground = false;
        w.settings.set_feet(&feet);
        let lifted = w.describe().unwrap_or_default();
        assert!(lifted.starts_with("3 of 4 feet on the ground."), "{lifted}");
    }

    #[test]
    fn a_link_of_the_first_format_still_opens() {
        // The first format: each foot's place and whether it stands, and the CoM.
        let feet = vec![
            ([0.2, 0.1], true),
            ([-0.2, 0.1], false),
            ([-0.2, -0.1], true),
            ([0.2, -0.1], true),
        ];
        let old = link::encode(&(feet.clone(), [0.05, -0.02])).unwrap_or_default();
        let mut w = widget(&[]);
        assert_eq!(w.restore(&old), Ok(()));
        assert_eq!(
            w.settings.feet,
            Some(feet.iter().map(|(at, _)| *at).collect())
        );
        assert_eq!(w.settings.lifted, Some(vec![2.0]));
        assert_eq!(w.settings.com, [0.05, -0.02]);
        assert_eq!(w.settings.grounded().len(), 3);
        // A foot off the ground plane: refused, the lesson's stance kept.
        let mut far = feet;
        far[0].0 = [3.0, 0.0];
        let bad = link::encode(&(far, [0.0, 0.0])).unwrap_or_default();
        let mut w = widget(&[("legs", "4")]);
        assert!(w.restore(&bad).is_err());
        assert_eq!(w.settings, w.initial);
    }

    #[test]
    fn a_moved_stance_travels_in_the_link() {
        let mut w = widget(&[("legs", "5")]);
        assert_eq!(w.state(), None);
        let mut feet = w.settings.feet();
        feet[1].at = [0.123_456_789, -0.3];
        feet[3].on_ground = false;
        w.settings.set_feet(&feet);
        w.settings.com = [0.01, 0.02];
        let text = w.state().unwrap_or_default();
        let mut again = widget(&[]);
        assert_eq!(again.restore(&text), Ok(()));
        assert_eq!(again.settings, w.settings);
        assert_eq!(again.settings.grounded().len(), 4);
        // Every foot down again: nothing lifted, and the link says so.
        feet[3].on_ground = true;
        w.settings.set_feet(&feet);
        assert_eq!(w.settings.lifted, None);
        assert!(w.state().is_some());
    }
}
