//! A case for each command from a seed number: usually a valid input with
//! a little damage, sometimes a lot, sometimes a path that is not a file.
//! [`valid_case`] makes the same kinds of case without damage, for tests
//! that need answers (the command line against the JavaScript package).

use serde_json::Value;

use crate::case::{Case, FileSpec, Sink, to_hex};
use crate::mutate::{Dice, damage_text, format_number, mutate_tree};
use crate::seeds::Seeds;

/// Every command the generators cover, with its share of the cases.
pub const COMMANDS: [(&str, u32); 37] = [
    ("leg-events", 2),
    ("stability", 4),
    ("analyze", 8),
    ("drive", 10),
    ("differential-drive", 2),
    ("robots", 2),
    ("simulate", 8),
    ("batch", 6),
    ("gains", 4),
    ("mechanisms", 1),
    ("describe", 3),
    ("home-state", 2),
    ("fk", 10),
    ("ik", 8),
    ("place", 3),
    ("jacobian", 3),
    ("dynamics", 4),
    ("statics", 3),
    ("collide", 4),
    ("field", 10),
    ("catalogues", 1),
    ("run", 8),
    ("lessons", 6),
    ("check-lesson", 3),
    ("widgets", 1),
    ("pick-cell", 3),
    ("gait", 6),
    ("cpg", 5),
    ("zmp", 3),
    ("walk", 3),
    ("ant", 2),
    ("plan", 6),
    ("arena", 3),
    ("routes", 2),
    ("components", 4),
    ("script", 3),
    ("usage", 4),
];

/// The case numbered `index` of the campaign `seed`.
pub fn case(seeds: &Seeds, seed: u64, index: u64) -> Case {
    let mut dice = Dice::new(kinolab_common::random::hash(seed, index, 0xf022));
    let total: u32 = COMMANDS.iter().map(|(_, w)| w).sum();
    let mut roll = dice.below(total as usize) as u32;
    let command = COMMANDS
        .iter()
        .find(|(_, w)| {
            let hit = roll < *w;
            roll = roll.saturating_sub(*w);
            hit
        })
        .map_or("usage", |(c, _)| c);
    let mut case = for_command(&mut dice, seeds, command, false);
    // Now and then the answer has nowhere to go.
    if dice.chance(0.01) {
        case.sink = *dice.pick(&[Sink::Full, Sink::Closed]);
    }
    case
}

/// A case of `command` with every input valid (numbers of everyday size,
/// files undamaged, options from their allowed values), numbered `index`
/// from `seed`. Valid input may still be refused for what it means: a
/// start inside an obstacle, a gait whose legs never touch down.
pub fn valid_case(seeds: &Seeds, command: &str, seed: u64, index: u64) -> Case {
    let mut dice = Dice::new(kinolab_common::random::hash(seed, index, 0x7a11d));
    for_command(&mut dice, seeds, command, true)
}

fn for_command(dice: &mut Dice, seeds: &Seeds, command: &str, valid: bool) -> Case {
    let mut g = Gen {
        dice,
        valid,
        case: Case::new(command, vec![command.to_owned()]),
    };
    match command {
        "leg-events" => {
            let legs = g.pick_text(
                &["1", "2", "6", "17"],
                &["0", "18", "100", "-1", "4294967296", "x"],
            );
            g.arg(&legs);
        }
        "stability" => {
            g.option_numbers("--com", 2);
            let feet: Vec<String> = (0..g.below(8, 3)).map(|_| g.numbers(2)).collect();
            g.option("--feet", &feet.join(";"));
        }
        "analyze" | "describe" | "home-state" => {
            let (seeds, ids, name) = if command == "analyze" {
                (&seeds.robots, &seeds.robot_ids, "robot.json")
            } else {
                (&seeds.models, &seeds.model_ids, "arm.model.json")
            };
            g.file_arg(seeds, ids, name);
        }
        "drive" => drive_case(&mut g, seeds),
        "differential-drive" => {
            let track = g.pick_text(&["0.3", "0.5", "1"], &["0", "-1", "nan", "1e308"]);
            g.option("--track", &track);
            g.option_numbers("--left", 1);
            g.option_numbers("--right", 1);
        }
        "robots" => {
            if g.dice.chance(0.7) {
                let id = if g.valid || g.dice.chance(0.8) {
                    g.dice.pick(&seeds.robot_ids).clone()
                } else {
                    g.dice.nasty_string()
                };
                g.arg(&id);
            }
        }
        "simulate" => {
            g.file_arg(&seeds.control_runs, &[], "run.json");
        }
        "batch" => batch_case(&mut g, seeds),
        "gains" => {
            let text = g.numbers(3);
            g.arg(&text);
        }
        "fk" | "ik" | "place" | "jacobian" | "collide" => model_case(&mut g, seeds, command),
        "dynamics" | "statics" => forces_case(&mut g, seeds, command),
        "field" => field_case(&mut g, seeds),
        "run" => {
            g.file_arg(&seeds.behaviour_runs, &[], "behaviours.run.json");
        }
        "lessons" | "check-lesson" => lessons_case(&mut g, seeds, command),
        "pick-cell" => pick_cell_case(&mut g),
        "gait" => gait_case(&mut g, seeds),
        "cpg" => {
            g.file_arg(&seeds.cpgs, &[], "net.cpg.json");
        }
        "zmp" => {
            g.file_arg(&seeds.pushes, &[], "push.zmp.json");
        }
        "ant" => {
            g.file_arg(&seeds.beaches, &[], "beach.ant.json");
        }
        "walk" => walk_case(&mut g, seeds),
        "plan" => plan_case(&mut g, seeds),
        "arena" => arena_case(&mut g, seeds),
        "routes" => routes_case(&mut g),
        "components" => components_case(&mut g, seeds),
        "script" => script_case(&mut g, seeds),
        "mechanisms" | "catalogues" | "widgets" => {}
        _ => usage_case(&mut g),
    }
    g.case
}

/// Builds one case.
struct Gen<'d> {
    dice: &'d mut Dice,
    /// Only valid input (see [`valid_case`]).
    valid: bool,
    case: Case,
}

impl Gen<'_> {
    fn arg(&mut self, text: &str) {
        self.case.args.push(text.to_owned());
    }

    fn flag(&mut self, name: &str) {
        self.arg(name);
    }

    fn option(&mut self, name: &str, value: &str) {
        self.arg(name);
        self.arg(value);
    }

    /// A number from 0 to `n` − 1; at least `least` when only valid input is made.
    fn below(&mut self, n: usize, least: usize) -> usize {
        let k = self.dice.below(n);
        if self.valid { k.max(least) } else { k }
    }

    /// `count` numbers for an option: of everyday size when valid, else
    /// sometimes extreme, malformed or too few.
    fn numbers(&mut self, count: usize) -> String {
        if !self.valid {
            return self.dice.numbers_text(count);
        }
        let parts: Vec<String> = (0..count)
            .map(|_| format_number((self.dice.range(-2.0, 2.0) * 100.0).round() / 100.0))
            .collect();
        parts.join(",")
    }

    fn option_numbers(&mut self, name: &str, count: usize) {
        let text = self.numbers(count);
        self.option(name, &text);
    }

    /// One of `valid`, or (unless only valid input is made) one of `invalid`.
    fn pick_text(&mut self, valid: &[&str], invalid: &[&str]) -> String {
        let n = if self.valid {
            valid.len()
        } else {
            valid.len() + invalid.len()
        };
        let k = self.dice.below(n);
        valid
            .get(k)
            .or_else(|| invalid.get(k - valid.len()))
            .map_or_else(String::new, |s| (*s).to_owned())
    }

    /// The input file: a seed (damaged or not), a catalogue id, or a path
    /// that is no file at all. Returns the seed text used, if any.
    fn file_arg(&mut self, seeds: &[String], ids: &[String], name: &str) -> Option<String> {
        if self.valid {
            return self.valid_file_arg(seeds, ids, name);
        }
        let roll = self.dice.below(100);
        if roll < 10 && !ids.is_empty() {
            let id = if self.dice.chance(0.85) {
                self.dice.pick(ids).clone()
            } else {
                self.dice.nasty_string()
            };
            self.arg(&format!("catalogue:{id}"));
            return None;
        }
        if roll < 16 || seeds.is_empty() {
            self.special_path(name);
            return None;
        }
        let seed = self.dice.pick(seeds).clone();
        let spec = if roll < 80 {
            FileSpec::Text(self.damaged_tree(&seed))
        } else {
            let bytes = damage_text(self.dice, &seed);
            match String::from_utf8(bytes) {
                Ok(text) if text.len() > 200_000 => FileSpec::Repeat {
                    text: text.chars().take(1).collect(),
                    count: text.len(),
                },
                Ok(text) => FileSpec::Text(text),
                Err(e) => FileSpec::Hex(to_hex(e.as_bytes())),
            }
        };
        let undamaged = matches!(&spec, FileSpec::Text(t) if *t == seed);
        self.case.files.push((name.to_owned(), spec));
        self.arg(name);
        undamaged.then_some(seed)
    }

    /// A catalogue id (a third of the time, when there are ids) or an
    /// undamaged seed file.
    fn valid_file_arg(&mut self, seeds: &[String], ids: &[String], name: &str) -> Option<String> {
        if !ids.is_empty() && (seeds.is_empty() || self.dice.chance(0.33)) {
            let id = self.dice.pick(ids).clone();
            self.arg(&format!("catalogue:{id}"));
            return None;
        }
        let seed = self.dice.pick(seeds).clone();
        self.case
            .files
            .push((name.to_owned(), FileSpec::Text(seed.clone())));
        self.arg(name);
        Some(seed)
    }

    /// The seed with a few values changed (none a fifth of the time).
    fn damaged_tree(&mut self, seed: &str) -> String {
        let Ok(mut tree) = serde_json::from_str::<Value>(seed) else {
            return seed.to_owned();
        };
        let count = *self.dice.pick(&[0, 0, 0, 1, 1, 2, 3, 6]);
        if count == 0 {
            return seed.to_owned();
        }
        mutate_tree(self.dice, &mut tree, count);
        tree.to_string()
    }

    fn special_path(&mut self, name: &str) {
        match self.dice.below(8) {
            0 => self.arg("missing.json"),
            1 => {
                self.case.files.push((name.to_owned(), FileSpec::Folder));
                self.arg(name);
            }
            2 => {
                self.case.files.push((name.to_owned(), FileSpec::Fifo));
                self.arg(name);
            }
            3 => self.arg("/dev/zero"),
            4 => self.arg("/dev/null"),
            5 => {
                let odd = "odd\nname.json";
                self.case
                    .files
                    .push((odd.to_owned(), FileSpec::Text("{".into())));
                self.arg(odd);
            }
            6 => {
                self.case.files.push((
                    name.to_owned(),
                    FileSpec::Repeat {
                        text: "n".into(),
                        count: 5_000_000,
                    },
                ));
                self.arg(name);
            }
            _ => {
                // A 3 MB key: under the size bound, too long to repeat.
                let text = format!("{{\"{}\": 1}}", "k".repeat(3_000_000));
                self.case
                    .files
                    .push((name.to_owned(), FileSpec::Text(text)));
                self.arg(name);
            }
        }
    }
}

/// A robot and a twist, spins (`-` for unknown) or neither.
fn drive_case(g: &mut Gen<'_>, seeds: &Seeds) {
    let seed = g.file_arg(&seeds.robots, &seeds.robot_ids, "robot.json");
    let wheels = match (g.valid, seed) {
        (true, Some(text)) => {
            kinolab_wheels::Chassis::from_json(&text).map_or(0, |c| c.wheels().len())
        }
        (true, None) => {
            let id = g
                .case
                .args
                .last()
                .and_then(|a| a.strip_prefix("catalogue:"))
                .unwrap_or_default();
            kinolab_wheels::catalogue::robot(id).map_or(0, |c| c.wheels().len())
        }
        _ => g.dice.below(7),
    };
    match g.dice.below(if g.valid { 4 } else { 5 }) {
        0 | 1 => g.option_numbers("--twist", 3),
        2 | 3 => {
            let spins: Vec<String> = (0..wheels)
                .map(|_| {
                    if g.dice.chance(0.2) {
                        "-".to_owned()
                    } else {
                        g.numbers(1)
                    }
                })
                .collect();
            g.option("--wheels", &spins.join(","));
        }
        _ => {}
    }
    if g.dice.chance(0.3) {
        g.option_numbers("--theta", 1);
    }
}

/// A run file and the circle of starts, sometimes with paths.
fn batch_case(g: &mut Gen<'_>, seeds: &Seeds) {
    g.file_arg(&seeds.control_runs, &[], "run.json");
    if g.dice.chance(0.5) {
        let radius = g.pick_text(&["0.5", "1", "2"], &["0", "-1", "1e9", "nan"]);
        g.option("--radius", &radius);
    }
    if g.dice.chance(0.5) {
        g.option_numbers("--heading-deg", 1);
    }
    if g.dice.chance(0.6) {
        let count = g.pick_text(
            &["1", "4", "8"],
            &["16", "100", "1000", "1001", "0", "-3", "1e3"],
        );
        g.option("--count", &count);
    }
    if g.dice.chance(0.3) {
        g.flag("--paths");
    }
}

/// A gait and sometimes a sample count.
fn gait_case(g: &mut Gen<'_>, seeds: &Seeds) {
    g.file_arg(&seeds.gaits, &seeds.gait_ids, "walk.gait.json");
    if g.dice.chance(0.4) {
        let n = g.pick_text(&["1", "7", "100"], &["1000", "100000", "100001", "0", "-1"]);
        g.option("--samples", &n);
    }
}

/// A six-legged gait, a lift, samples and sometimes a stride.
fn walk_case(g: &mut Gen<'_>, seeds: &Seeds) {
    let hexapods: Vec<String> = seeds
        .gait_ids
        .iter()
        .filter(|id| id.starts_with("hexapod"))
        .cloned()
        .collect();
    let files: Vec<String> = seeds
        .gaits
        .iter()
        .filter(|g| g.matches("\"name\"").count() > 6)
        .cloned()
        .collect();
    g.file_arg(&files, &hexapods, "walk.gait.json");
    if g.dice.chance(0.6) {
        let lift = g.pick_text(&["0.01", "0.03", "0.05"], &["-1", "nan", "50"]);
        g.option("--lift", &lift);
    }
    let samples = g.pick_text(&["4", "12", "24"], &["0", "5000", "-1"]);
    g.option("--samples", &samples);
    if g.dice.chance(0.3) {
        let stride = g.pick_text(&["0.05", "0.1", "0.2"], &["-0.5", "9"]);
        g.option("--stride", &stride);
    }
}

/// Exercises cheap enough to grade inside a case's time limit.
const QUICK_EXERCISES: [&str; 3] = ["control-park", "field-pull", "legs-walk"];

/// `script exercises`, `script check SCRIPT --exercise ID` or `script
/// grade --exercise ID FILES... [--csv]`, with the exercises' solutions
/// (damaged or not) as scripts.
fn script_case(g: &mut Gen<'_>, seeds: &Seeds) {
    let mode = g.pick_text(&["exercises", "check", "grade"], &["run", ""]);
    g.arg(&mode);
    let exercise = g.pick_text(&QUICK_EXERCISES, &["no-such-exercise", ""]);
    match mode.as_str() {
        "check" => {
            script_file(g, seeds, "mine.rhai");
            g.option("--exercise", &exercise);
        }
        "grade" => {
            g.option("--exercise", &exercise);
            for name in ["ana.rhai", "ben.rhai"].iter().take(1 + g.below(2, 0)) {
                script_file(g, seeds, name);
            }
            if g.dice.chance(0.5) {
                g.flag("--csv");
            }
        }
        _ => {}
    }
}

/// A learner's script: a seed, a few characters changed unless only valid
/// input is made.
fn script_file(g: &mut Gen<'_>, seeds: &Seeds, name: &str) {
    if !g.valid && g.dice.chance(0.2) {
        g.special_path(name);
        return;
    }
    let seed = g.dice.pick(&seeds.scripts).clone();
    let text = if g.valid {
        seed
    } else {
        String::from_utf8_lossy(&damage_text(g.dice, &seed)).into_owned()
    };
    g.case.files.push((name.to_owned(), FileSpec::Text(text)));
    g.arg(name);
}

/// The world a case names (its file's text or its catalogue id).
fn world_of(g: &Gen<'_>, seed: Option<String>) -> Option<kinolab_world::World> {
    match seed {
        Some(text) => kinolab_world::World::from_json(&text).ok(),
        None => g
            .case
            .args
            .last()
            .and_then(|a| a.strip_prefix("catalogue:"))
            .and_then(|id| kinolab_world::catalogue::world(id).ok()),
    }
}

/// A world, two points (usually inside it; its start and goal when only
/// valid input is made and it has them) and a cell size.
fn plan_case(g: &mut Gen<'_>, seeds: &Seeds) {
    let seed = g.file_arg(&seeds.worlds, &seeds.world_ids, "map.world.json");
    let ends = world_of(g, seed)
        .filter(|_| g.valid)
        .and_then(|w| Some((w.start, w.goal?)));
    for (k, option) in ["--from", "--to"].into_iter().enumerate() {
        if g.valid || g.dice.chance(0.95) {
            let p = match ends {
                Some((start, _)) if k == 0 => [start.x, start.y],
                Some((_, goal)) => [goal.x, goal.y],
                None => [g.dice.range(-1.0, 12.0), g.dice.range(-1.0, 8.0)],
            };
            let text = if g.valid || g.dice.chance(0.85) {
                format!("{:.2},{:.2}", p[0], p[1])
            } else {
                g.dice.numbers_text(2)
            };
            g.option(option, &text);
        }
    }
    if g.valid || g.dice.chance(0.95) {
        let cell = g.pick_text(
            &["0.1", "0.25", "0.5", "1"],
            &["0.001", "0", "-1", "100", "1e-6"],
        );
        g.option("--cell", &cell);
    }
    if g.dice.chance(0.2) {
        let algorithm = g.pick_text(&["astar", "dijkstra"], &["bfs"]);
        g.option("--algorithm", &algorithm);
    }
}

/// A world, an architecture, a few surprises (some broken) and short runs.
fn arena_case(g: &mut Gen<'_>, seeds: &Seeds) {
    if g.valid {
        // The arena needs a goal to drive to.
        let goals: Vec<String> = seeds
            .world_ids
            .iter()
            .filter(|id| kinolab_world::catalogue::world(id).is_ok_and(|w| w.goal.is_some()))
            .cloned()
            .collect();
        g.valid_file_arg(&[], &goals, "arena.world.json");
    } else {
        g.file_arg(&seeds.worlds, &seeds.world_ids, "arena.world.json");
    }
    if g.valid || g.dice.chance(0.95) {
        let kind = g.pick_text(
            &["hierarchical", "reactive", "hybrid"],
            &["deliberative", ""],
        );
        g.option("--architecture", &kind);
    }
    for _ in 0..g.dice.below(3) {
        let spec = g.pick_text(
            &[
                "noise:0.15",
                "noise:5",
                "glass:8.2,0,8.2,3.2",
                "glass:-50,0,1,1",
            ],
            &[
                "door:5,1,5,2@6",
                "person:6.3,5.6,6.3,2.0@0.6",
                "wrong-map:0",
                "wrong-map:99",
                "goal:9,5@3",
                "door:1,1@2",
                "teleport:1,1",
                "person:1,1,2,2@0",
            ],
        );
        g.option("--perturb", &spec);
    }
    let cost = g.pick_text(&["0", "2", "20"], &["1000", "-1", "nan", "1e308"]);
    g.option("--planning-cost", &cost);
    let duration = g.pick_text(&["3", "8"], &["0", "-3", "1e9", "nan"]);
    g.option("--duration", &duration);
    if g.dice.chance(0.5) {
        let every = g.pick_text(&["1", "10"], &["0", "1000000"]);
        g.option("--every", &every);
    }
}

fn components_case(g: &mut Gen<'_>, seeds: &Seeds) {
    if g.dice.chance(0.1) {
        let id = g.pick_text(&["robot", "events", "out-of-order"], &["nowhere", ""]);
        g.arg(&format!("example:{id}"));
    } else {
        g.file_arg(&seeds.systems, &[], "lab.system.json");
    }
    if g.dice.chance(0.6) {
        let until = g.pick_text(&["0", "1", "30"], &["600", "601", "-1", "nan", "1e308"]);
        g.option("--until", &until);
    }
}

/// The joint count of the model the case names.
fn dof_of(g: &mut Gen<'_>, seed: Option<String>) -> usize {
    let model = match seed {
        Some(s) => kinolab_mechanism::file::from_json(&s).ok(),
        None => g
            .case
            .args
            .last()
            .and_then(|a| a.strip_prefix("catalogue:"))
            .and_then(|id| kinolab_mechanism::catalogue::mechanism(id).ok()),
    };
    match model {
        Some(m) => m.dof(),
        None => g.dice.below(8),
    }
}

fn model_case(g: &mut Gen<'_>, seeds: &Seeds, command: &str) {
    let seed = g.file_arg(&seeds.models, &seeds.model_ids, "arm.model.json");
    let dof = dof_of(g, seed);
    if command != "ik" || g.dice.chance(0.4) {
        let q_option = if command == "ik" { "--seed" } else { "--q" };
        g.option_numbers(q_option, dof);
    }
    match command {
        "ik" => ik_options(g),
        "collide" => collide_options(g),
        _ => {}
    }
    if command != "place" && command != "collide" && g.dice.chance(0.2) {
        let frame = g.pick_text(&["tool", "base", "world"], &["q1", "nope", "tool\ntool"]);
        g.option("--frame", &frame);
    }
}

/// `dynamics` (inverse or forward) or `statics` (loads, springs) of a
/// model at some joint values.
fn forces_case(g: &mut Gen<'_>, seeds: &Seeds, command: &str) {
    let seed = g.file_arg(&seeds.models, &seeds.model_ids, "arm.model.json");
    let dof = dof_of(g, seed);
    g.option_numbers("--q", dof);
    if g.dice.chance(0.3) {
        g.option_numbers("--gravity", 3);
    }
    if command == "dynamics" {
        if g.dice.chance(0.6) {
            g.option_numbers("--qd", dof);
        }
        let asked = if g.dice.chance(0.5) { "--qdd" } else { "--tau" };
        g.option_numbers(asked, dof);
        return;
    }
    for _ in 0..g.dice.below(3) {
        let frame = g.pick_text(&["tool", "base"], &["nope", ""]);
        let count = if g.dice.chance(0.5) { 3 } else { 6 };
        let values = g.numbers(count);
        g.option("--load", &format!("{frame}:{values}"));
    }
    if g.dice.chance(0.5) {
        let k = g.pick_text(&["2000", "150.5"], &["0", "-3", "x"]);
        g.option("--stiffness", &k);
    }
}

fn ik_options(g: &mut Gen<'_>) {
    g.option_numbers("--position", 3);
    if g.dice.chance(0.3) {
        let rotation = if g.valid || g.dice.chance(0.5) {
            let a: f64 = g.dice.range(-3.0, 3.0);
            let (s, c) = a.sin_cos();
            format!("{c},{},0,{s},{c},0,0,0,1", -s)
        } else {
            g.dice.numbers_text(9)
        };
        g.option("--rotation", &rotation);
    }
    if g.dice.chance(0.2) {
        let n = g.pick_text(&["5", "50"], &["0", "100000"]);
        g.option("--max-iterations", &n);
    }
}

fn collide_options(g: &mut Gen<'_>) {
    let plane = g.pick_text(&["plan", "side"], &["top", ""]);
    g.option("--plane", &plane);
    for _ in 0..g.dice.below(3) {
        let kind = g.pick_text(&["circle:", "rect:"], &["square:", ""]);
        let numbers = if g.valid {
            let size = |g: &mut Gen<'_>| format!("{:.2}", g.dice.range(0.05, 0.5));
            let centre = g.numbers(2);
            let sizes: Vec<String> = (0..if kind == "circle:" { 1 } else { 2 })
                .map(|_| size(g))
                .collect();
            format!("{centre},{}", sizes.join(","))
        } else {
            g.numbers(if kind == "circle:" { 3 } else { 4 })
        };
        g.option("--obstacle", &format!("{kind}{numbers}"));
    }
}

fn field_case(g: &mut Gen<'_>, seeds: &Seeds) {
    g.file_arg(&seeds.fields, &seeds.field_ids, "map.field.json");
    match g.dice.below(if g.valid { 3 } else { 4 }) {
        0 => {
            let points: Vec<String> = (0..g.dice.below(5) + 1).map(|_| g.numbers(2)).collect();
            g.option("--at", &points.join(";"));
        }
        1 => {
            g.flag("--minima");
            if g.valid {
                g.option("--box", "-1,-3,7,3");
            } else if g.dice.chance(0.9) {
                g.option_numbers("--box", 4);
            }
        }
        2 => {
            g.option_numbers("--descend", 2);
            if g.dice.chance(0.4) {
                let step = g.pick_text(&["0.01", "0.05", "0.2"], &["0", "-1", "nan"]);
                g.option("--step", &step);
            }
            if g.dice.chance(0.4) {
                let steps = g.pick_text(&["1", "100", "10000"], &["1000000", "0", "-1"]);
                g.option("--max-steps", &steps);
            }
        }
        _ => {
            if g.dice.chance(0.5) {
                g.option_numbers("--at", 2);
                g.flag("--minima");
            }
        }
    }
}

/// A folder of one unit and one lesson (`lessons`), or the lesson alone
/// (`check-lesson`).
fn lessons_case(g: &mut Gen<'_>, seeds: &Seeds, command: &str) {
    if command == "lessons" && (g.valid || g.dice.chance(0.1)) {
        return;
    }
    let lesson = g.dice.pick(&seeds.lessons).clone();
    let text = match if g.valid { 0 } else { g.dice.below(6) } {
        0 => lesson,
        1 => format!("{lesson}\n{} deep\n", ">".repeat(g.dice.below(20_000) + 1)),
        2 => format!("{lesson}\n{}x\n", "- ".repeat(g.dice.below(20_000) + 1)),
        3 => format!("{lesson}\n{}x{}\n", "*".repeat(5000), "*".repeat(5000)),
        4 => String::from_utf8_lossy(&damage_text(g.dice, &lesson)).into_owned(),
        _ => lesson.replace("minutes: 3", &format!("minutes: {}", g.dice.nasty_string())),
    };
    if command == "check-lesson" {
        g.case
            .files
            .push(("01-lesson.md".to_owned(), FileSpec::Text(text)));
        g.arg("01-lesson.md");
        return;
    }
    let unit = "---\ntitle: A unit\n---\n\nWhat the unit is about.\n";
    g.case.files.push((
        "course/01-unit/unit.md".to_owned(),
        FileSpec::Text(unit.into()),
    ));
    g.case.files.push((
        "course/01-unit/01-lesson.md".to_owned(),
        FileSpec::Text(text),
    ));
    g.arg("course");
}

fn pick_cell_case(g: &mut Gen<'_>) {
    for option in ["--placement-error", "--gripper-tolerance", "--sensor-error"] {
        let value = g.pick_text(&["0", "0.002", "0.01", "0.05"], &["-1", "nan", "1e308"]);
        g.option(option, &value);
    }
    if g.dice.chance(0.6) {
        let count = g.pick_text(&["1", "10", "500"], &["0", "100001", "-1"]);
        g.option("--count", &count);
    }
    if g.dice.chance(0.5) {
        let seed = g.pick_text(&["1", "7", "4294967295"], &["-1", "x"]);
        g.option("--seed", &seed);
    }
}

/// Six rows of five 0/1 marks, sometimes malformed.
fn routes_case(g: &mut Gen<'_>) {
    let rows: Vec<String> = (0..6)
        .map(|_| {
            (0..5)
                .map(|_| if g.dice.chance(0.3) { '1' } else { '0' })
                .collect()
        })
        .collect();
    let mut text = rows.join(";");
    if !g.valid && g.dice.chance(0.3) {
        text = g.pick_text(&[], &["10;01", "1111x;0;0;0;0;0", "", "0000000;0;0;0;0;0"]);
    }
    g.arg(&text);
}

fn usage_case(g: &mut Gen<'_>) {
    g.case.args.clear();
    match g.dice.below(6) {
        0 => {}
        1 => g.arg("--bogus"),
        2 => g.arg("no-such-command"),
        3 => g.arg("fk"),
        4 => {
            g.arg("ik");
            g.arg("catalogue:puma560");
        }
        _ => {
            g.arg("gains");
            g.arg("1,2,3");
            g.arg("--extra\nline");
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn cases_are_reproducible_and_cover_every_command() {
        let seeds = Seeds::load();
        assert!(!seeds.robots.is_empty() && !seeds.fields.is_empty());
        assert!(!seeds.behaviour_runs.is_empty() && !seeds.worlds.is_empty());
        assert_eq!(case(&seeds, 1, 5), case(&seeds, 1, 5));
        let commands: std::collections::BTreeSet<String> =
            (0..2000).map(|i| case(&seeds, 1, i).command).collect();
        assert_eq!(commands.len(), COMMANDS.len(), "{commands:?}");
    }
}
