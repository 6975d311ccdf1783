//! The pitch background: grass with mowing stripes, the markings of Law 1 and both goals, drawn
//! once per resolution with tiny-skia (anti-aliased) and copied under every frame.

use tiny_skia::{Color, FillRule, Paint, PathBuilder, Pixmap, Rect, Stroke, Transform};
use touchline_engine::geometry::pitch::{
    CENTRE_CIRCLE_RADIUS, GOAL_DEPTH, GOAL_HALF_WIDTH, HALF_LENGTH, HALF_WIDTH, PENALTY_AREA_DEPTH,
    PENALTY_AREA_HALF_WIDTH, PENALTY_MARK_DISTANCE,
};

use crate::layout::Layout;
use crate::palette;

/// Depth of the goal area from the goal line (m, Law 1: 5.5 m).
const GOAL_AREA_DEPTH: f32 = 5.5;
/// Half width of the goal area: 5.5 m beyond each post (Law 1).
const GOAL_AREA_HALF_WIDTH: f32 = GOAL_HALF_WIDTH + 5.5;
/// Width of a mowing stripe (m); 10 stripes per half of GRF's 110 m pitch.
const STRIPE_WIDTH: f32 = 5.5;
/// Drawn width of the lines (m). Law 1 allows up to 12 cm; thicker here so that they survive
/// small images.
const LINE_WIDTH: f32 = 0.25;

/// Paints the background for `layout` into `pixmap` (which has the layout's size).
pub(crate) fn paint(pixmap: &mut Pixmap, layout: &Layout) {
    pixmap.fill(colour(palette::SURROUND));
    let t = layout.transform();
    let mut paint = Paint { anti_alias: true, ..Paint::default() };

    // Grass over the rim, then the stripes inside the lines.
    paint.set_color(colour(palette::GRASS));
    fill_rect(
        pixmap,
        &paint,
        t,
        -HALF_LENGTH - 5.0,
        -HALF_WIDTH - 4.0,
        2.0 * HALF_LENGTH + 10.0,
        2.0 * HALF_WIDTH + 8.0,
    );
    paint.set_color(colour(palette::GRASS_STRIPE));
    let stripes = (2.0 * HALF_LENGTH / STRIPE_WIDTH) as usize;
    for i in (1..stripes).step_by(2) {
        let x = -HALF_LENGTH + i as f32 * STRIPE_WIDTH;
        fill_rect(pixmap, &paint, t, x, -HALF_WIDTH, STRIPE_WIDTH, 2.0 * HALF_WIDTH);
    }

    // Nets behind the goal lines.
    paint.set_color(colour(palette::NET));
    for sign in [-1.0f32, 1.0] {
        let x = if sign < 0.0 { -HALF_LENGTH - GOAL_DEPTH } else { HALF_LENGTH };
        fill_rect(pixmap, &paint, t, x, -GOAL_HALF_WIDTH, GOAL_DEPTH, 2.0 * GOAL_HALF_WIDTH);
    }

    // Markings (Law 1).
    let mut lines = PathBuilder::new();
    if let Some(r) = Rect::from_xywh(-HALF_LENGTH, -HALF_WIDTH, 2.0 * HALF_LENGTH, 2.0 * HALF_WIDTH) {
        lines.push_rect(r);
    }
    lines.move_to(0.0, -HALF_WIDTH);
    lines.line_to(0.0, HALF_WIDTH);
    lines.push_circle(0.0, 0.0, CENTRE_CIRCLE_RADIUS);
    for sign in [-1.0f32, 1.0] {
        let line = sign * HALF_LENGTH;
        for (depth, half) in [(PENALTY_AREA_DEPTH, PENALTY_AREA_HALF_WIDTH), (GOAL_AREA_DEPTH, GOAL_AREA_HALF_WIDTH)] {
            lines.move_to(line, -half);
            lines.line_to(line - sign * depth, -half);
            lines.line_to(line - sign * depth, half);
            lines.line_to(line, half);
        }
        // The penalty arc: the part of the 9.15 m circle round the mark outside the area.
        let spot = line - sign * PENALTY_MARK_DISTANCE;
        let edge = PENALTY_AREA_DEPTH - PENALTY_MARK_DISTANCE;
        let reach = libm::acosf(edge / CENTRE_CIRCLE_RADIUS);
        const SEGMENTS: usize = 24;
        for k in 0..=SEGMENTS {
            let a = -reach + 2.0 * reach * k as f32 / SEGMENTS as f32;
            let x = spot - sign * CENTRE_CIRCLE_RADIUS * libm::cosf(a);
            let y = CENTRE_CIRCLE_RADIUS * libm::sinf(a);
            if k == 0 { lines.move_to(x, y) } else { lines.line_to(x, y) }
        }
        // The goal frame: posts and the net's outline.
        lines.move_to(line, -GOAL_HALF_WIDTH);
        lines.line_to(line + sign * GOAL_DEPTH, -GOAL_HALF_WIDTH);
        lines.line_to(line + sign * GOAL_DEPTH, GOAL_HALF_WIDTH);
        lines.line_to(line, GOAL_HALF_WIDTH);
    }
    let stroke = Stroke { width: (LINE_WIDTH * layout.scale).max(1.0) / layout.scale, ..Stroke::default() };
    paint.set_color(colour(palette::LINE));
    if let Some(path) = lines.finish() {
        pixmap.stroke_path(&path, &paint, &stroke, t, None);
    }

    // Spots: centre and both penalty marks.
    let mut spots = PathBuilder::new();
    let spot_radius = (0.3 * layout.scale).max(0.7) / layout.scale;
    for x in [0.0, -HALF_LENGTH + PENALTY_MARK_DISTANCE, HALF_LENGTH - PENALTY_MARK_DISTANCE] {
        spots.push_circle(x, 0.0, spot_radius);
    }
    if let Some(path) = spots.finish() {
        pixmap.fill_path(&path, &paint, FillRule::Winding, t, None);
    }
}

/// Fills the rectangle at `(x, y)` of size `w` × `h` (m).
fn fill_rect(pixmap: &mut Pixmap, paint: &Paint, t: Transform, x: f32, y: f32, w: f32, h: f32) {
    if let Some(r) = Rect::from_xywh(x, y, w, h) {
        pixmap.fill_rect(r, paint, t, None);
    }
}

/// The colour of an opaque RGB triple, for tiny-skia.
fn colour([r, g, b]: [u8; 3]) -> Color {
    Color::from_rgba8(r, g, b, 255)
}
