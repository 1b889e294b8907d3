//! Braitenberg vehicles: a few vehicles and lights; wire each vehicle
//! (straight or crossed, excitatory or inhibitory, gain and base speed) or
//! pick one of the four classic characters, and watch.

use egui::{RichText, Sense, Slider, vec2};
use kinolab_behaviours::braitenberg::{Character, Sign, Wiring};
use kinolab_behaviours::library::{Behaviour, Named};
use kinolab_behaviours::{Drive, Response};
use kinolab_world::{Body, Light, Pose, Sensors, Sim, World};
use serde::{Deserialize, Serialize};

use super::world_view::{color, draw_robot, draw_trail, draw_world};
use crate::draw::{PlaneView, handle};
use crate::link;
use crate::widget::{LabWidget, Params};

/// What the learner sets, and what a link carries.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
struct Design {
    wirings: Vec<Wiring>,
    lights: Vec<[f64; 2]>,
}

struct Vehicle {
    sim: Sim,
    brain: Named,
    trail: Vec<[f64; 2]>,
}

struct Vehicles {
    design: Design,
    initial: Design,
    vehicles: Vec<Vehicle>,
    drive: Drive,
    playing: bool,
}

/// Where the vehicles start: spread along the room's left side.
const STARTS: [[f64; 3]; 4] = [
    [1.0, 4.5, -0.3],
    [1.0, 1.5, 0.3],
    [2.0, 5.2, -0.6],
    [2.0, 0.8, 0.6],
];
const TRAIL: usize = 1500;

pub fn create(p: &Params) -> Result<Box<dyn LabWidget>, String> {
    let names = p.text("vehicles").unwrap_or("love, fear");
    let wirings = names
        .split(',')
        .map(|n| {
            Character::ALL
                .into_iter()
                .find(|c| c.name() == n.trim())
                .map(Character::wiring)
                .ok_or_else(|| format!("no character `{}`", n.trim()))
        })
        .collect::<Result<Vec<_>, _>>()?;
    let world = room();
    let design = Design {
        wirings,
        lights: world.lights.iter().map(|l| [l.x, l.y]).collect(),
    };
    let mut v = Vehicles {
        initial: design.clone(),
        design,
        vehicles: Vec::new(),
        drive: Drive {
            body: Body::default(),
            heading_gain: 3.0,
        },
        playing: true,
    };
    v.reset();
    Ok(Box::new(v))
}

/// An 8 × 6 m room with two lights and nothing else.
fn room() -> World {
    let mut world = World::empty("lights", kinolab_world::Rect::from([0.0, 0.0, 8.0, 6.0]));
    world.lights = vec![
        Light {
            x: 5.5,
            y: 4.0,
            intensity: 4.0,
        },
        Light {
            x: 4.5,
            y: 1.5,
            intensity: 4.0,
        },
    ];
    world
}

impl Vehicles {
    /// Put every vehicle back at its start with the current wiring.
    fn reset(&mut self) {
        let mut world = room();
        world.lights = self
            .design
            .lights
            .iter()
            .map(|l| Light {
                x: l[0],
                y: l[1],
                intensity: 4.0,
            })
            .collect();
        let sensors = Sensors {
            lights: Some(Default::default()),
            ..Sensors::default()
        };
        self.vehicles = self
            .design
            .wirings
            .iter()
            .zip(STARTS)
            .filter_map(|(w, [x, y, theta])| {
                let mut world = world.clone();
                world.start = Pose::new(x, y, theta);
                let sim = Sim::new(world, self.drive.body.clone(), sensors, 0.05, 1).ok()?;
                Some(Vehicle {
                    sim,
                    brain: Named::new(w.character().name(), Behaviour::Braitenberg(*w)),
                    trail: vec![[x, y]],
                })
            })
            .collect();
    }

    fn step(&mut self) {
        for v in &mut self.vehicles {
            let percepts = v.sim.sense();
            let response = v
                .brain
                .respond(&percepts)
                .unwrap_or(Response::Wheels([0.0, 0.0]));
            v.sim.advance(self.drive.command(&response));
            if v.trail.len() < TRAIL {
                v.trail.push([v.sim.pose.x, v.sim.pose.y]);
            }
        }
    }

    fn canvas(&mut self, ui: &mut egui::Ui, width: f32) {
        let (rect, _) = ui.allocate_exact_size(vec2(width, width * 0.75), Sense::hover());
        let view = PlaneView::fit(rect.shrink(4.0), [0.0, 0.0], [8.0, 6.0]);
        let painter = ui.painter_at(rect);
        let ink = ui.visuals().text_color();
        if let Some(first) = self.vehicles.first() {
            draw_world(ui, &painter, &view, &first.sim.world, 0.0);
        }
        for (i, v) in self.vehicles.iter().enumerate() {
            draw_trail(
                &painter,
                &view,
                v.trail.iter().copied(),
                color(i).gamma_multiply(0.7),
            );
            draw_robot(
                &painter,
                &view,
                &v.sim.pose,
                v.sim.body.radius(),
                color(i),
                ink,
            );
        }
        let base = ui.scope_id().with("lights");
        let mut moved = false;
        for k in 0..self.design.lights.len() {
            let l = self.design.lights[k];
            let h = handle(
                ui,
                base.with(k),
                view.to_screen(l),
                12.0,
                &format!("Light {}", k + 1),
            );
            if let Some([x, y]) = h.dragged_to(&view, l) {
                self.design.lights[k] = [x.clamp(0.2, 7.8), y.clamp(0.2, 5.8)];
                moved = true;
            }
        }
        if moved {
            for v in &mut self.vehicles {
                for (light, at) in v.sim.world.lights.iter_mut().zip(&self.design.lights) {
                    light.x = at[0];
                    light.y = at[1];
                }
            }
        }
    }

    fn wiring_ui(&mut self, ui: &mut egui::Ui) -> bool {
        let mut changed = false;
        for (i, w) in self.design.wirings.iter_mut().enumerate() {
            ui.push_id(i, |ui| {
                ui.label(
                    RichText::new(format!(
                        "Vehicle {} ({} · {})",
                        i + 1,
                        w.character().vehicle(),
                        w.character().name()
                    ))
                    .color(color(i))
                    .strong(),
                );
                ui.horizontal_wrapped(|ui| {
                    for c in Character::ALL {
                        if ui
                            .small_button(c.vehicle())
                            .on_hover_text(c.name())
                            .clicked()
                        {
                            *w = c.wiring();
                            changed = true;
                        }
                    }
                });
                let before = *w;
                ui.horizontal(|ui| {
                    ui.checkbox(&mut w.crossed, "crossed");
                    ui.radio_value(&mut w.sign, Sign::Excitatory, "excitatory");
                    ui.radio_value(&mut w.sign, Sign::Inhibitory, "inhibitory");
                });
                ui.add(Slider::new(&mut w.gain, 0.0..=6.0).text("gain w"));
                ui.add(Slider::new(&mut w.base, 0.0..=10.0).text("base (rad/s)"));
                changed |= *w != before;
            });
        }
        changed
    }
}

impl LabWidget for Vehicles {
    fn ui(&mut self, ui: &mut egui::Ui) {
        if self.playing {
            self.step();
            crate::widget::animate(ui);
        }
        ui.horizontal(|ui| {
            if ui
                .button(if self.playing { "Pause" } else { "Play" })
                .clicked()
            {
                self.playing = !self.playing;
            }
            if ui.button("Start again").clicked() {
                self.reset();
                self.playing = true;
            }
        });
        let wide = ui.available_width() >= 760.0;
        let changed = if wide {
            let w = ui.available_width() * 0.62;
            ui.horizontal_top(|ui| {
                self.canvas(ui, w);
                ui.vertical(|ui| self.wiring_ui(ui)).inner
            })
            .inner
        } else {
            self.canvas(ui, ui.available_width());
            self.wiring_ui(ui)
        };
        if changed {
            for (v, w) in self.vehicles.iter_mut().zip(&self.design.wirings) {
                v.brain = Named::new(w.character().name(), Behaviour::Braitenberg(*w));
            }
        }
        ui.label(RichText::new("Drag the lights. Straight wiring joins each sensor to its own side's wheel; crossed, to the other side's.").small());
    }

    fn state(&self) -> Option<String> {
        link::changed(&self.design, &self.initial)
    }

    fn restore(&mut self, state: &str) -> Result<(), String> {
        if let Some(d) = link::decode::<Design>(state)
            && !d.wirings.is_empty()
            && d.wirings.len() <= 4
            && d.wirings.iter().all(|w| w.check().is_ok())
            && d.lights.iter().flatten().all(|v| v.is_finite())
        {
            self.design = d;
            self.reset();
        }
        Ok(())
    }
}
