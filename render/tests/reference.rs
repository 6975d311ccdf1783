//! Rendered frames of a fixed scene compared with the checked-in reference images in
//! `tests/reference/`.
//!
//! Tolerance: at least 99.5 % of the pixels must match the reference within 8 levels in every
//! channel, and the mean absolute difference over all channels must stay under 0.5 levels. The
//! players, ball and scoreboard are drawn with correctly rounded arithmetic and match exactly;
//! the slack is for tiny-skia's anti-aliased pitch lines, whose SIMD paths may round differently
//! on other CPUs. To regenerate the images after a deliberate change of the drawing, run
//! `TOUCHLINE_BLESS=1 cargo nextest run -p touchline-render --test reference` and look at them.

use std::path::PathBuf;

use touchline_engine::{GameMode, Side};
use touchline_render::{PixelsEncoder, PixelsKind, RenderOptions, Renderer, Scene, ScenePlayer};

/// A moment of a match, written out by hand so that it does not change when the engine's play
/// does: 4-4-2 against 4-4-2, a right-back with the ball, a lofted ball on its way, a corner
/// pending, 2-1 after 1234 steps.
fn known_scene() -> Scene {
    let shape: [(f32, f32); 11] = [
        (-50.0, 0.0),
        (-35.0, -20.0),
        (-37.0, -7.0),
        (-37.0, 7.0),
        (-35.0, 20.0),
        (-15.0, -24.0),
        (-18.0, -8.0),
        (-18.0, 8.0),
        (-15.0, 24.0),
        (-3.0, -6.0),
        (-4.0, 9.0),
    ];
    let mut players = Vec::new();
    for side in [Side::Left, Side::Right] {
        let sign = if side == Side::Left { 1.0 } else { -1.0 };
        for (i, &(x, y)) in shape.iter().enumerate() {
            players.push(ScenePlayer {
                side,
                number: i as u8 + 1,
                goalkeeper: i == 0,
                position: [sign * x + if side == Side::Left { 12.0 } else { 0.0 }, sign * y],
                controlled: side == Side::Left && i == 9,
                has_ball: side == Side::Right && i == 4,
                on_pitch: !(side == Side::Right && i == 10),
            });
        }
    }
    Scene { players, ball: [20.0, 12.0, 3.5], score: [2, 1], steps: 1234, mode: GameMode::Corner }
}

fn reference_path(name: &str) -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("tests/reference").join(name)
}

/// Compares `pixels` (`width × height`, `channels` per pixel) with the PNG `name`, or writes it
/// when `TOUCHLINE_BLESS` is set.
fn check(name: &str, width: usize, height: usize, channels: usize, pixels: &[u8]) {
    let path = reference_path(name);
    let colour = match channels {
        1 => png::ColorType::Grayscale,
        3 => png::ColorType::Rgb,
        _ => png::ColorType::Rgba,
    };
    if std::env::var_os("TOUCHLINE_BLESS").is_some() {
        let file = std::fs::File::create(&path).expect("create reference");
        let mut encoder = png::Encoder::new(std::io::BufWriter::new(file), width as u32, height as u32);
        encoder.set_color(colour);
        encoder.set_depth(png::BitDepth::Eight);
        encoder.write_header().expect("png header").write_image_data(pixels).expect("png data");
        return;
    }
    let file = std::fs::File::open(&path).unwrap_or_else(|e| panic!("{}: {e} (bless to create it)", path.display()));
    let mut decoder = png::Decoder::new(std::io::BufReader::new(file)).read_info().expect("png");
    let mut reference = vec![0; decoder.output_buffer_size().expect("size")];
    let info = decoder.next_frame(&mut reference).expect("png frame");
    assert_eq!((info.width as usize, info.height as usize, info.color_type), (width, height, colour), "{name}: shape");
    let reference = &reference[..info.buffer_size()];
    assert_eq!(reference.len(), pixels.len());
    let mut off = 0usize;
    let mut total = 0u64;
    for (a, b) in pixels.chunks_exact(channels).zip(reference.chunks_exact(channels)) {
        let worst = a.iter().zip(b).map(|(x, y)| x.abs_diff(*y)).max().unwrap_or(0);
        off += usize::from(worst > 8);
        total += a.iter().zip(b).map(|(x, y)| u64::from(x.abs_diff(*y))).sum::<u64>();
    }
    let n = width * height;
    let mean = total as f64 / pixels.len() as f64;
    assert!(off * 200 <= n, "{name}: {off} of {n} pixels differ by more than 8 levels");
    assert!(mean < 0.5, "{name}: mean absolute difference {mean:.3}");
}

#[test]
fn frame_1280x720_with_scoreboard() {
    let mut r = Renderer::new(1280, 720, RenderOptions::default()).expect("renderer");
    let frame = r.render(&known_scene()).to_vec();
    check("known_scene_1280x720.png", 1280, 720, 4, &frame);
}

#[test]
fn frame_320x240_with_scoreboard() {
    let mut r = Renderer::new(320, 240, RenderOptions::default()).expect("renderer");
    let frame = r.render(&known_scene()).to_vec();
    check("known_scene_320x240.png", 320, 240, 4, &frame);
}

#[test]
fn pixels_96x72() {
    let mut e = PixelsEncoder::new(96, 72, PixelsKind::Rgb).expect("encoder");
    let mut out = vec![0; e.len()];
    e.encode_scene(&known_scene(), &mut out);
    check("known_scene_pixels_96x72.png", 96, 72, 3, &out);
}

#[test]
fn pixels_gray_96x72() {
    let mut e = PixelsEncoder::new(96, 72, PixelsKind::Gray).expect("encoder");
    let mut out = vec![0; e.len()];
    e.encode_scene(&known_scene(), &mut out);
    check("known_scene_pixels_gray_96x72.png", 96, 72, 1, &out);
}

#[test]
fn rendering_is_a_pure_function_of_the_scene() {
    let mut a = Renderer::new(200, 150, RenderOptions::default()).expect("renderer");
    let mut b = a.clone();
    let scene = known_scene();
    let first = a.render(&scene).to_vec();
    // Another scene in between leaves no trace.
    b.render(&Scene::default());
    assert_eq!(b.render(&scene), &first[..]);
    assert_eq!(a.render(&scene), &first[..]);
}

#[test]
fn every_part_of_the_scene_shows() {
    let scene = known_scene();
    let mut r = Renderer::new(640, 360, RenderOptions::default()).expect("renderer");
    let base = r.render(&scene).to_vec();
    let differs = |s: &Scene, r: &mut Renderer| r.render(s) != &base[..];
    let mut s = scene.clone();
    s.ball[2] = 0.11;
    assert!(differs(&s, &mut r), "ball height");
    let mut s = scene.clone();
    s.players[9].controlled = false;
    assert!(differs(&s, &mut r), "controlled ring");
    let mut s = scene.clone();
    s.players[15].has_ball = false;
    assert!(differs(&s, &mut r), "ball carrier marker");
    let mut s = scene.clone();
    s.score = [3, 1];
    assert!(differs(&s, &mut r), "score");
    let mut s = scene.clone();
    s.steps += 40;
    assert!(differs(&s, &mut r), "clock");
    let mut s = scene.clone();
    s.mode = GameMode::Normal;
    assert!(differs(&s, &mut r), "game mode");
    let mut s = scene.clone();
    s.players[3].number = 44;
    assert!(differs(&s, &mut r), "shirt number");
    let mut s = scene.clone();
    s.players[21].on_pitch = true;
    assert!(differs(&s, &mut r), "sent-off player hidden");
}
