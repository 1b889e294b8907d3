//! Graded exercises on gaits, checked by the core so the lab, a test and
//! an instructor's script agree.

use kinolab_common::Feedback;
use kinolab_common::display::fixed;

use crate::error::FieldError;
use crate::gait::{Gait, min_margin};

/// Samples over the cycle an answer is checked at.
const CHECK_SAMPLES: usize = 720;

/// "Find lift-off phases that keep this walker statically stable with duty
/// factor `beta`": met when the gait keeps β and its margin stays positive
/// at every checked instant.
pub fn static_phases(gait: &Gait, beta: f64) -> Result<Feedback, FieldError> {
    gait.check()?;
    if (gait.duty_factor - beta).abs() > 1e-9 {
        return Ok(Feedback::not_yet(format!(
            "Keep the duty factor at β = {}: change only the phases.",
            fixed(beta, 2)
        )));
    }
    let instants = gait.sample(CHECK_SAMPLES);
    if let Some(m) = min_margin(&instants).filter(|m| *m > 0.0) {
        // How close to the best this answer is (quadrupeds: a small search).
        let best = best_phases(gait)
            .ok()
            .flatten()
            .map_or(String::new(), |(_, b)| {
                format!(
                    " The best phases on a 1/12-cycle grid reach {} cm.",
                    fixed(b.max(m) * 100.0, 1)
                )
            });
        return Ok(Feedback::met(format!(
            "Statically stable through the whole cycle: the smallest margin is {} cm.{best}",
            fixed(m * 100.0, 1)
        )));
    }
    let worst = instants
        .iter()
        .min_by(|a, b| {
            let m = |s: &crate::gait::Instant| s.margin.unwrap_or(f64::NEG_INFINITY);
            m(a).total_cmp(&m(b))
        })
        .ok_or_else(|| FieldError::new("legs", "no instant to check"))?;
    let down: Vec<&str> = worst
        .stance
        .iter()
        .map(|&i| gait.legs[i].name.as_str())
        .collect();
    let margin = worst.margin.map_or("no foot is down".to_owned(), |m| {
        format!("the margin is {} cm", fixed(m * 100.0, 1))
    });
    Ok(Feedback::not_yet(format!(
        "Not yet: at τ = {} {margin} with {} down. Spread the lift-offs so that \
         legs on the same side or the same diagonal do not swing together.",
        fixed(worst.tau, 3),
        if down.is_empty() {
            "nothing".to_owned()
        } else {
            down.join(", ")
        }
    )))
}

/// "Find the largest push the ankle can still catch": a body at rest over
/// the ankle (x = 0) of `table`'s foot, pushed forwards at `push` m/s. The
/// answer is ω times the distance to the toe (the capture point must stay
/// on the foot); within 5 % below it counts.
pub fn largest_push(table: &crate::balance::CartTable, push: f64) -> Result<Feedback, FieldError> {
    let push = kinolab_common::error::in_range("push", push, 0.0, 20.0)?;
    let limit = table.omega() * table.toe;
    let caught = table.push(0.0, push, 6.0, 0.005)?.recovered;
    Ok(if !caught {
        Feedback::not_yet(format!(
            "At {push:.3} m/s the capture point passes the toe: the ZMP the body needs leaves the foot and it falls. Push less."
        ))
    } else if push < 0.95 * limit {
        Feedback::not_yet(format!(
            "{push:.3} m/s is caught, but a harder push would be too. Push more."
        ))
    } else {
        Feedback::met(format!(
            "{push:.3} m/s is caught, and the limit is ω · toe = {:.3} m/s. Beyond it the capture point lies past the toe.",
            limit
        ))
    })
}

/// "Set the couplings so the oscillators lock into a trot": run `net` from
/// eight seeded starts for 20 cycles; every run must end with the trot's
/// lags (LF and RH together, RF and LH half a cycle later) within 0.01.
pub fn lock_trot(net: &crate::network::Network) -> Feedback {
    if let Err(e) = net.check() {
        return Feedback::not_yet(e.to_string());
    }
    if net.phases.len() != 4 {
        return Feedback::not_yet("The trot needs four legs.");
    }
    let trot = [0.0, 0.5, 0.5, 0.0];
    let duration = 20.0 / net.frequency.max(0.2);
    let h = 0.002_f64.min(0.02 / net.frequency.max(0.2));
    let steps = (duration / h).ceil() as usize;
    for start in 0..8u64 {
        let theta: Vec<f64> = (0..4)
            .map(|i| std::f64::consts::TAU * kinolab_common::random::unit_hash(start, i, 11))
            .collect();
        let mut s = net.start(&theta);
        for _ in 0..steps {
            net.step(&mut s, h);
        }
        let lags = net.lags(&s);
        let worst = lags
            .iter()
            .zip(trot)
            .map(|(l, t)| crate::cpg::cycle_distance(*l, t))
            .fold(0.0, f64::max);
        if worst > 0.01 {
            return Feedback::not_yet(format!(
                "From start {} the lags end at {} cycles, not the trot's 0, 0.5, 0.5, 0.",
                start + 1,
                lags.iter()
                    .map(|l| fixed(*l, 2))
                    .collect::<Vec<_>>()
                    .join(", ")
            ));
        }
    }
    Feedback::met("From every start the diagonal pairs lock together, half a cycle apart: a trot.")
}

/// Grid steps per cycle the phase search tries for each leg.
pub const SEARCH_STEPS: usize = 12;

/// The backend of the phase exercises: for `gait`'s duty factor, feet and
/// CoM, the lift-off phases (the first leg's fixed at 0, the others on a
/// grid of 1/12 cycle) with the largest smallest margin over the cycle,
/// and that margin. Four legs at most (12³ candidates); `None` when no
/// candidate has a foot down at every instant.
pub fn best_phases(gait: &Gait) -> Result<Option<(Vec<f64>, f64)>, FieldError> {
    gait.check()?;
    let n = gait.legs.len();
    if n > 4 {
        return Err(FieldError::new(
            "legs",
            format!("the search tries up to 4 legs, got {n}"),
        ));
    }
    let mut best: Option<(Vec<f64>, f64)> = None;
    let mut trial = gait.clone();
    let combos = SEARCH_STEPS.pow(n.saturating_sub(1) as u32);
    for code in 0..combos {
        let mut rest = code;
        for leg in trial.legs.iter_mut().skip(1) {
            leg.phase = (rest % SEARCH_STEPS) as f64 / SEARCH_STEPS as f64;
            rest /= SEARCH_STEPS;
        }
        trial.legs[0].phase = 0.0;
        if let Some(margin) = min_margin(&trial.sample(48))
            && best.as_ref().is_none_or(|(_, m)| margin > *m + 1e-12)
        {
            best = Some((trial.legs.iter().map(|l| l.phase).collect(), margin));
        }
    }
    Ok(best)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_crawl_order_passes_and_a_pace_order_fails() {
        let mut g = crate::named("quadruped-crawl").unwrap();
        g.duty_factor = 0.8;
        assert!(static_phases(&g, 0.8).unwrap().met);
        // LF and LH lifting together leave the CoM off the right-hand pair.
        for (leg, phase) in g.legs.iter_mut().zip([0.0, 0.5, 0.0, 0.5]) {
            leg.phase = phase;
        }
        let f = static_phases(&g, 0.8).unwrap();
        assert!(!f.met && f.message.contains("τ ="), "{}", f.message);
        g.duty_factor = 0.9;
        assert!(static_phases(&g, 0.8).unwrap().message.contains("β = 0.80"));
    }

    #[test]
    fn the_largest_push_is_omega_times_the_toe() {
        let table = crate::balance::CartTable::new(0.8, -0.05, 0.15).unwrap();
        let limit = table.omega() * 0.15;
        assert!(largest_push(&table, 0.98 * limit).unwrap().met);
        assert!(!largest_push(&table, 0.8 * limit).unwrap().met);
        let over = largest_push(&table, 1.02 * limit).unwrap();
        assert!(
            !over.met && over.message.contains("passes the toe"),
            "{}",
            over.message
        );
        assert_eq!(largest_push(&table, f64::NAN).unwrap_err().field, "push");
    }

    #[test]
    fn the_trot_locks_only_with_its_offsets_and_some_coupling() {
        let net = |gait: &str, w: f64| {
            let g = crate::named(gait).unwrap();
            let mut weights = vec![vec![w; 4]; 4];
            for (i, row) in weights.iter_mut().enumerate() {
                row[i] = 0.0;
            }
            crate::network::Network {
                model: crate::network::Model::Phase,
                frequency: 1.0,
                phases: g.legs.iter().map(|l| l.phase).collect(),
                weights,
                mu: 1.0,
            }
        };
        assert!(lock_trot(&net("quadruped-trot", 1.0)).met);
        assert!(!lock_trot(&net("quadruped-pace", 1.0)).met);
        assert!(!lock_trot(&net("quadruped-trot", 0.0)).met);
    }

    #[test]
    fn the_best_phases_obey_mcghee_and_frank() {
        let mut crawl = crate::named("quadruped-crawl").unwrap();
        crawl.duty_factor = 0.8;
        let (phases, margin) = best_phases(&crawl).unwrap().unwrap();
        assert!(margin > 0.0, "{phases:?}: {margin}");
        // The answer passes the learner's task at the same β.
        let mut answer = crawl.clone();
        for (leg, p) in answer.legs.iter_mut().zip(&phases) {
            leg.phase = *p;
        }
        assert!(static_phases(&answer, 0.8).unwrap().met);
        // Below β = 3/4 no phases stand at every instant.
        crawl.duty_factor = 0.7;
        let (_, margin) = best_phases(&crawl).unwrap().unwrap();
        assert!(margin <= 1e-12, "{margin}");
        assert_eq!(
            best_phases(&crate::named("hexapod-wave").unwrap())
                .unwrap_err()
                .field,
            "legs"
        );
    }
}
