//! Reading the controller playground's lesson parameters and link state.

use kinolab_control::{Direction, Gains, Pose, Segment};

/// `x, y, heading_deg` as a pose.
pub(super) fn pose(key: &str, text: &str) -> Result<Pose, String> {
    match triple(text).as_deref() {
        Some([x, y, h]) => Ok(Pose::new(*x, *y, h.to_radians())),
        _ => Err(format!(
            "Parameter `{key}` must be `x, y, heading_deg` (three numbers), found `{text}`."
        )),
    }
}

/// `k_rho, k_alpha, k_beta`.
pub(super) fn gains(key: &str, text: &str) -> Result<Gains, String> {
    match triple(text).as_deref() {
        Some([r, a, b]) => Gains::new(*r, *a, *b).map_err(|e| e.to_string()),
        _ => Err(format!(
            "Parameter `{key}` must be `k_rho, k_alpha, k_beta` (three numbers), found `{text}`."
        )),
    }
}

fn triple(text: &str) -> Option<Vec<f64>> {
    let v: Vec<f64> = text
        .split(',')
        .map(|p| p.trim().parse::<f64>().ok().filter(|x| x.is_finite()))
        .collect::<Option<_>>()?;
    (v.len() == 3).then_some(v)
}

pub(super) fn direction(text: &str) -> Result<Direction, String> {
    match text {
        "auto" => Ok(Direction::Auto),
        "forward" => Ok(Direction::Forward),
        "backward" => Ok(Direction::Backward),
        other => Err(format!(
            "Parameter `direction` must be auto, forward or backward, found `{other}`."
        )),
    }
}

pub(super) fn direction_name(d: Direction) -> &'static str {
    match d {
        Direction::Auto => "auto",
        Direction::Forward => "forward",
        Direction::Backward => "backward",
    }
}

/// A plan written as `line 1; arc 0.5 90; turn -90`.
pub(super) fn plan(text: &str) -> Result<Vec<Segment>, String> {
    let mut out = Vec::new();
    for (i, part) in text
        .split(';')
        .map(str::trim)
        .filter(|p| !p.is_empty())
        .enumerate()
    {
        let words: Vec<&str> = part.split_whitespace().collect();
        let nums: Option<Vec<f64>> = words[1..]
            .iter()
            .map(|w| w.parse::<f64>().ok().filter(|x| x.is_finite()))
            .collect();
        let segment = match (words[0], nums.as_deref()) {
            ("line", Some([length])) => Segment::Line { length: *length },
            ("arc", Some([radius, deg])) if *radius > 0.0 => Segment::Arc {
                radius: *radius,
                angle: deg.to_radians(),
            },
            ("turn", Some([deg])) => Segment::Turn {
                angle: deg.to_radians(),
            },
            _ => {
                return Err(format!(
                    "Segment {} (`{part}`): write `line METRES`, `arc RADIUS DEGREES` (radius > 0) or `turn DEGREES`.",
                    i + 1
                ));
            }
        };
        out.push(segment);
    }
    if out.is_empty() {
        return Err("The plan is empty: add a segment such as `line 1`.".into());
    }
    if out.len() > kinolab_control::MAX_SEGMENTS {
        return Err(format!(
            "At most {} segments.",
            kinolab_control::MAX_SEGMENTS
        ));
    }
    Ok(out)
}

/// Gain sets separated by `;`.
pub(super) fn gain_sets(text: &str) -> Result<Vec<Gains>, String> {
    let sets: Vec<Gains> = text
        .split(';')
        .map(str::trim)
        .filter(|p| !p.is_empty())
        .map(|p| gains("sets", p))
        .collect::<Result<_, _>>()?;
    if sets.len() < 2 {
        return Err("Parameter `sets` needs at least two gain sets separated by `;`.".into());
    }
    Ok(sets)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn parameters_parse_and_explain_mistakes() {
        let p = pose("start", "-1, 0.5, 90").unwrap_or_default();
        assert!((p.theta - std::f64::consts::FRAC_PI_2).abs() < 1e-15 && p.x == -1.0);
        assert!(pose("start", "1, 2").is_err_and(|e| e.contains("`start`")));
        assert!(gains("gains", "3, 8, -1.5").is_ok_and(|g| g == kinolab_control::TEXTBOOK_GAINS));
        let segs = plan("line 1; arc 0.5 90;turn -45 ").unwrap_or_default();
        assert_eq!(segs.len(), 3);
        assert!(
            matches!(segs[2], Segment::Turn { angle } if (angle + std::f64::consts::FRAC_PI_4).abs() < 1e-15)
        );
        assert!(plan("line 1; arc -0.5 90").is_err_and(|e| e.starts_with("Segment 2")));
        assert!(plan("jump 3").is_err());
        assert!(plan(" ; ").is_err());
        assert!(gain_sets("3,8,-1.5; 3,2,-1.5").is_ok_and(|s| s.len() == 2));
        assert!(direction("sideways").is_err());
    }
}
