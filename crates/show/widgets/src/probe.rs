//! Named points on the screen that a browser test can aim at: a port of
//! the component lab, a service. Widgets publish them while they draw; the
//! app's shell collects them once the frame is drawn, and the web shell
//! writes them on the page (canvas content has no elements to find).
//! Nothing is published until a host asks for it with [`enable`]: the web
//! shell does when the page's address carries `?probe`.

use std::collections::BTreeMap;

fn id() -> egui::Id {
    egui::Id::unique("kinolab-probe-points")
}

fn switch() -> egui::Id {
    egui::Id::unique("kinolab-probe-on")
}

/// Start publishing points (a test is watching).
pub fn enable(ctx: &egui::Context) {
    ctx.data_mut(|d| d.insert_temp(switch(), true));
}

/// Whether a host asked for points.
pub fn enabled(ctx: &egui::Context) -> bool {
    ctx.data(|d| d.get_temp::<bool>(switch())).unwrap_or(false)
}

/// Publish where `name` is drawn this frame, in points (when enabled).
pub fn publish(ctx: &egui::Context, name: &str, at: egui::Pos2) {
    if !enabled(ctx) {
        return;
    }
    ctx.data_mut(|d| {
        d.get_temp_mut_or_default::<BTreeMap<String, egui::Pos2>>(id())
            .insert(name.to_owned(), at);
    });
}

/// Every point published since the last call, by name, and forget them.
pub fn take(ctx: &egui::Context) -> BTreeMap<String, egui::Pos2> {
    ctx.data_mut(|d| d.remove_temp::<BTreeMap<String, egui::Pos2>>(id()))
        .unwrap_or_default()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn points_are_taken_once_and_the_last_position_wins() {
        let ctx = egui::Context::default();
        publish(&ctx, "motion.source", egui::pos2(1.0, 2.0));
        assert!(take(&ctx).is_empty(), "nothing until a host asks");
        enable(&ctx);
        publish(&ctx, "motion.source", egui::pos2(1.0, 2.0));
        publish(&ctx, "planner.route", egui::pos2(3.0, 4.0));
        publish(&ctx, "motion.source", egui::pos2(5.0, 6.0));
        let points = take(&ctx);
        assert_eq!(points.len(), 2);
        assert_eq!(points["motion.source"], egui::pos2(5.0, 6.0));
        assert!(take(&ctx).is_empty());
    }
}
