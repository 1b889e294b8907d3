//! The lab's first frame lays out only what fits on the screen, so that a
//! learner who opens the lab sees the page sooner. The next frame, asked
//! for at once, lays out the rest, before anything below the screen could
//! be seen, reached with the keyboard or read aloud.

/// Where a page's first frame stops laying out.
#[derive(Debug, Default, Clone, Copy)]
pub struct FirstScreen {
    /// Lay out only what fits on the screen (the lab's first frame).
    only: bool,
    /// Something was left for the next frame.
    cut: bool,
}

impl FirstScreen {
    /// For a frame: the first (`first`) stops at the screen's edge.
    pub fn new(first: bool) -> Self {
        Self {
            only: first,
            cut: false,
        }
    }

    /// Whether to stop laying out `ui` here, because the rest lies below
    /// the screen on the first frame; the next frame is then asked for.
    pub fn stop(&mut self, ui: &egui::Ui) -> bool {
        let below = self.only && ui.cursor().top() > ui.clip_rect().bottom();
        if below && !self.cut {
            ui.ctx().request_repaint();
        }
        self.cut |= below;
        below
    }

    /// Whether this frame left part of the page for the next.
    pub fn cut(&self) -> bool {
        self.cut
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A column of 40 rows of 30 points in a 200-point-high screen: the
    /// first frame stops after the rows that reach the screen, and asks
    /// for another frame; any later frame lays out every row.
    fn rows_laid_out(first: bool) -> (usize, bool, bool) {
        let ctx = egui::Context::default();
        let input = egui::RawInput {
            screen_rect: Some(egui::Rect::from_min_size(
                egui::Pos2::ZERO,
                egui::vec2(300.0, 200.0),
            )),
            ..Default::default()
        };
        let mut screen = FirstScreen::new(first);
        let mut rows = 0;
        let mut output = ctx.run_ui(input, |ui| {
            for _ in 0..40 {
                if screen.stop(ui) {
                    break;
                }
                ui.allocate_space(egui::vec2(100.0, 30.0));
                rows += 1;
            }
        });
        output.textures_delta.clear();
        let asked = output
            .viewport_output
            .values()
            .any(|v| v.repaint_delay.is_zero());
        (rows, screen.cut(), asked)
    }

    #[test]
    fn the_first_frame_stops_below_the_screen_and_asks_for_the_next() {
        let (rows, cut, asked) = rows_laid_out(true);
        assert!(cut && asked);
        // Every row that starts on the screen is laid out; none below it.
        let spacing = egui::Style::default().spacing.item_spacing.y;
        let on_screen = (200.0 / (30.0 + spacing)).ceil() as usize;
        assert!((on_screen..=on_screen + 1).contains(&rows), "{rows} rows");
        assert!(rows < 40);
    }

    #[test]
    fn later_frames_lay_out_everything() {
        let (rows, cut, _) = rows_laid_out(false);
        assert_eq!((rows, cut), (40, false));
    }
}
