//! Technology churn: the same robot application designed twice, as a graph
//! of classes. In the stable design, business logic uses business objects
//! (AnyRangeSensor, AnyBase, AnyChannel) and only the configuration names
//! the industrial objects; in the naive one, business logic names them
//! directly. Replacing an industrial object means editing every class that
//! names it.

use serde::Serialize;

use crate::FieldError;

/// The layers of a stable model.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
pub enum Layer {
    /// Business logic written for this application (the intelligence).
    Logic,
    /// A business object: a stable interface.
    Bo,
    /// An industrial object: a replaceable implementation.
    Io,
}

#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Class {
    pub name: &'static str,
    pub layer: Layer,
}

/// A design: classes and who names whom in its code.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Design {
    pub name: &'static str,
    pub classes: Vec<Class>,
    /// (user, used).
    pub uses: Vec<(&'static str, &'static str)>,
}

/// The industrial objects a learner can replace, and what replaces them.
pub const SWAPS: [(&str, &str); 3] = [
    ("SickLaser", "a different laser scanner"),
    ("Pioneer3DX", "a different mobile base"),
    ("RosTopics", "a different middleware"),
];

const LOGIC: [&str; 4] = ["Navigator", "Mapper", "Planner", "Localizer"];
const IOS: [&str; 3] = ["SickLaser", "Pioneer3DX", "RosTopics"];

fn classes(bos: &[&'static str]) -> Vec<Class> {
    let logic = LOGIC.iter().map(|&name| Class {
        name,
        layer: Layer::Logic,
    });
    let bo = bos.iter().map(|&name| Class {
        name,
        layer: Layer::Bo,
    });
    let io = IOS.iter().chain(&["Configuration"]).map(|&name| Class {
        name,
        layer: Layer::Io,
    });
    logic.chain(bo).chain(io).collect()
}

/// What each piece of logic needs: a range sensor, a base, a channel.
const NEEDS: [(&str, [bool; 3]); 4] = [
    ("Navigator", [true, true, true]),
    ("Mapper", [true, false, true]),
    ("Planner", [false, false, true]),
    ("Localizer", [true, true, false]),
];

/// Business logic over business objects; the configuration alone names
/// the industrial objects, which implement the business objects.
pub fn stable() -> Design {
    let bos = ["AnyRangeSensor", "AnyBase", "AnyChannel"];
    let mut uses = Vec::new();
    for (logic, needs) in NEEDS {
        for (k, need) in needs.iter().enumerate() {
            if *need {
                uses.push((logic, bos[k]));
            }
        }
    }
    for (io, bo) in IOS.iter().zip(bos) {
        uses.push((*io, bo));
        uses.push(("Configuration", *io));
    }
    Design {
        name: "stable",
        classes: classes(&bos),
        uses,
    }
}

/// Business logic that names the industrial objects itself.
pub fn naive() -> Design {
    let mut uses = Vec::new();
    for (logic, needs) in NEEDS {
        for (k, need) in needs.iter().enumerate() {
            if *need {
                uses.push((logic, IOS[k]));
            }
        }
    }
    for io in IOS {
        uses.push(("Configuration", io));
    }
    Design {
        name: "naive",
        classes: classes(&[]),
        uses,
    }
}

impl Design {
    /// The classes whose code must be edited when `io` is replaced: every
    /// class that names it.
    pub fn churn(&self, io: &str) -> Result<Vec<&'static str>, FieldError> {
        if !IOS.contains(&io) {
            return Err(FieldError::new(
                "io",
                format!("no industrial object `{io}`"),
            ));
        }
        Ok(self
            .uses
            .iter()
            .filter(|(_, used)| *used == io)
            .map(|(user, _)| *user)
            .filter(|user| !IOS.contains(user))
            .collect())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_stable_design_edits_only_its_configuration() {
        // Counted by hand from the two drawings.
        let cases = [("SickLaser", 3), ("Pioneer3DX", 2), ("RosTopics", 3)];
        for (io, naive_edits) in cases {
            assert_eq!(stable().churn(io).unwrap(), ["Configuration"]);
            let n = naive().churn(io).unwrap();
            assert_eq!(n.len(), naive_edits + 1, "{io}: {n:?}");
            assert!(n.contains(&"Configuration"));
        }
        assert_eq!(naive().churn("Navigator").unwrap_err().field, "io");
    }
}
