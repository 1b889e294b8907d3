//! Braitenberg's vehicles: two light sensors wired to two wheels.
//!
//! Straight wiring joins each sensor to the wheel on its own side, crossed
//! wiring to the other side. An excitatory link speeds its wheel up with
//! the reading (base + w·s); an inhibitory one slows it (base − w·s, never
//! below standing still).

use serde::{Deserialize, Serialize};

use crate::FieldError;

/// Whether a reading speeds its wheel up or slows it down.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Sign {
    Excitatory,
    Inhibitory,
}

/// How a vehicle's sensors drive its wheels.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Wiring {
    /// Left sensor to right wheel and right sensor to left wheel.
    pub crossed: bool,
    pub sign: Sign,
    /// w: wheel speed per unit of reading, rad/s.
    pub gain: f64,
    /// The wheel speed with no light, rad/s.
    pub base: f64,
}

/// The four classic characters.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Character {
    /// 2a: straight, excitatory: turns away and speeds off.
    Fear,
    /// 2b: crossed, excitatory: turns towards the light and hits it.
    Aggression,
    /// 3a: straight, inhibitory: turns towards it and comes to rest facing it.
    Love,
    /// 3b: crossed, inhibitory: slows near it, then turns away and leaves.
    Explorer,
}

impl Character {
    pub const ALL: [Character; 4] = [
        Character::Fear,
        Character::Aggression,
        Character::Love,
        Character::Explorer,
    ];

    /// Braitenberg's number for the vehicle.
    pub fn vehicle(self) -> &'static str {
        match self {
            Character::Fear => "2a",
            Character::Aggression => "2b",
            Character::Love => "3a",
            Character::Explorer => "3b",
        }
    }

    pub fn name(self) -> &'static str {
        match self {
            Character::Fear => "fear",
            Character::Aggression => "aggression",
            Character::Love => "love",
            Character::Explorer => "explorer",
        }
    }

    /// The wiring that makes this character, for the lab's default robot
    /// (wheels up to 10 rad/s) and lights of intensity about 4.
    pub fn wiring(self) -> Wiring {
        let (crossed, sign, gain, base) = match self {
            Character::Fear => (false, Sign::Excitatory, 3.0, 4.0),
            Character::Aggression => (true, Sign::Excitatory, 3.0, 4.0),
            Character::Love => (false, Sign::Inhibitory, 3.0, 6.0),
            Character::Explorer => (true, Sign::Inhibitory, 3.0, 6.0),
        };
        Wiring {
            crossed,
            sign,
            gain,
            base,
        }
    }
}

impl Wiring {
    pub fn check(&self) -> Result<(), FieldError> {
        use kinolab_common::error::{finite, non_negative};
        finite("gain", self.gain)?;
        non_negative("base", self.base)?;
        Ok(())
    }

    /// Left and right wheel speeds for light readings `[left, right]`.
    pub fn wheels(&self, light: [f64; 2]) -> [f64; 2] {
        let [left_in, right_in] = if self.crossed {
            [light[1], light[0]]
        } else {
            light
        };
        let drive = |s: f64| match self.sign {
            Sign::Excitatory => self.base + self.gain * s,
            Sign::Inhibitory => (self.base - self.gain * s).max(0.0),
        };
        [drive(left_in), drive(right_in)]
    }

    /// Which classic character this wiring is, whatever its numbers.
    pub fn character(&self) -> Character {
        match (self.crossed, self.sign) {
            (false, Sign::Excitatory) => Character::Fear,
            (true, Sign::Excitatory) => Character::Aggression,
            (false, Sign::Inhibitory) => Character::Love,
            (true, Sign::Inhibitory) => Character::Explorer,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn wiring_follows_the_table() {
        // The light on the left: the left sensor reads 2, the right 1.
        let light = [2.0, 1.0];
        let [l, r] = Character::Fear.wiring().wheels(light);
        assert!(l > r, "2a: the left wheel runs faster, turning right, away");
        let [l, r] = Character::Aggression.wiring().wheels(light);
        assert!(
            r > l,
            "2b: the right wheel runs faster, turning left, towards"
        );
        let [l, r] = Character::Love.wiring().wheels(light);
        assert!(r > l, "3a: the left wheel slows, turning left, towards");
        let [l, r] = Character::Explorer.wiring().wheels(light);
        assert!(l > r, "3b: the right wheel slows, turning right, away");
        assert_eq!(
            Character::Love.wiring().wheels([9.0, 9.0]),
            [0.0, 0.0],
            "never backwards"
        );
        for c in Character::ALL {
            assert_eq!(c.wiring().character(), c);
        }
    }
}
