//! Randomised placements: values and points a scenario draws afresh at every reset.
//!
//! Units are GRF's normalised pitch coordinates (x in [-1, 1], y in [-0.42, 0.42];
//! docs/grf-compatibility.md#scenario-semantics). A player's spot is in its team's own frame, the ball's in
//! the global frame. Draws come from the episode's placement stream (see
//! [`Scenario::draw`](super::Scenario::draw)), so a seed fixes them.

use serde::{Deserialize, Serialize};

use super::placement::Anchor;
use crate::geometry::coords::SCENARIO_LINES;
use crate::rng::MatchRng;

/// The pitch lines in normalised units, |x| ≤ 1 ([`SCENARIO_LINES`]). Normal draws are clipped to
/// them ("normal clipped to the pitch").
pub const PITCH_HALF_LENGTH: f32 = SCENARIO_LINES[0];
/// Half the pitch width in normalised units, 0.42 ([`SCENARIO_LINES`]).
pub const PITCH_HALF_WIDTH: f32 = SCENARIO_LINES[1];

/// One coordinate: a number, or a distribution drawn at every reset.
///
/// JSON: a number (`0.5`), or one of `{"uniform": [low, high]}`, `{"normal": [mean, std]}`,
/// `{"choice": [v1, v2, …]}`, or `{"shared": KEY, "of": <distribution>}`.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(untagged)]
pub enum Sample {
    /// A fixed value.
    Fixed(f32),
    /// A value drawn from a distribution.
    Random(Distribution),
    /// A value drawn from a distribution once per placement and shared by every sample with the
    /// same key (`.tl`: a `param` holding a distribution, used in several places).
    Shared(Shared),
}

/// A draw shared by the samples of one key: the underlying uniform, normal or pick is drawn once
/// per placement (at the first sample of the key met), and each sample maps it through its own
/// distribution, so `uniform(-5 m, 5 m)` shared by a player and the ball, converted to each one's
/// units, puts both at the same metre.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Shared {
    /// Samples with the same key share one draw.
    pub shared: u32,
    /// This sample's distribution.
    pub of: Distribution,
}

/// The shared draws of one placement, by key: `(key, underlying value)`.
pub(crate) type SharedDraws = Vec<(u32, f32)>;

/// A distribution of one coordinate.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case", deny_unknown_fields)]
pub enum Distribution {
    /// Uniform on `[low, high]`.
    Uniform(f32, f32),
    /// Gaussian with `(mean, std)`, clipped to the pitch lines of its axis.
    Normal(f32, f32),
    /// One of the values, each equally likely.
    Choice(Vec<f32>),
}

/// An area of the pitch, in normalised units.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case", deny_unknown_fields)]
pub enum Region {
    /// The axis-aligned rectangle `x[0] ≤ x ≤ x[1]`, `y[0] ≤ y ≤ y[1]`.
    Rect {
        /// `[min, max]` along the pitch.
        x: [f32; 2],
        /// `[min, max]` across the pitch.
        y: [f32; 2],
    },
    /// The disc of radius `r` (normalised x units on both axes) around `(x, y)`.
    Circle {
        /// Centre x.
        x: f32,
        /// Centre y.
        y: f32,
        /// Radius.
        r: f32,
    },
}

/// Where a randomised player or ball starts.
///
/// JSON: `{"point": {"x": <Sample>, "y": <Sample>}}`, `{"in": <Region>}`,
/// `{"one_of": [[x, y], …]}` or `{"relative": {"of": <Body>, "offset": [dx, dy], "radius": r}}`.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case", deny_unknown_fields)]
pub enum Spot {
    /// Each coordinate fixed or drawn on its own.
    Point {
        /// x coordinate.
        x: Sample,
        /// y coordinate.
        y: Sample,
    },
    /// A point drawn uniformly in a region.
    In(Region),
    /// One of the points, each equally likely.
    OneOf(Vec<[f32; 2]>),
    /// A point taken from another body's position in the same draw (see [`Anchor`]); placed by
    /// [`Scenario::draw`](super::Scenario::draw) after that body.
    Relative(Anchor),
}

impl Sample {
    /// Draws the value; `limit` is the half-extent of the axis a normal draw is clipped to;
    /// `shared` holds this placement's shared draws.
    pub(crate) fn draw(&self, rng: &mut MatchRng, limit: f32, shared: &mut SharedDraws) -> f32 {
        match self {
            Sample::Fixed(v) => *v,
            Sample::Random(d) => d.draw(rng, limit),
            Sample::Shared(s) => {
                let underlying = match shared.iter().find(|(key, _)| *key == s.shared) {
                    Some(&(_, u)) => u,
                    None => {
                        let u = s.of.underlying(rng);
                        shared.push((s.shared, u));
                        u
                    }
                };
                s.of.map(underlying, limit)
            }
        }
    }

    /// The distribution, if the value is drawn.
    fn distribution(&self) -> Option<&Distribution> {
        match self {
            Sample::Fixed(_) => None,
            Sample::Random(d) | Sample::Shared(Shared { of: d, .. }) => Some(d),
        }
    }

    /// The value a reader sees without drawing: the fixed value or the distribution's centre.
    pub fn nominal(&self) -> f32 {
        match self {
            Sample::Fixed(v) => *v,
            Sample::Random(_) | Sample::Shared(_) => match self.distribution() {
                Some(Distribution::Uniform(a, b)) => 0.5 * (a + b),
                Some(Distribution::Normal(mean, _)) => *mean,
                Some(Distribution::Choice(values)) => values.first().copied().unwrap_or(0.0),
                None => 0.0,
            },
        }
    }

    /// Checks parameters: finite, `low ≤ high`, `std ≥ 0`, a non-empty choice.
    pub(crate) fn check(&self) -> Result<(), String> {
        let finite = |vs: &[f32]| vs.iter().all(|v| v.is_finite());
        match self {
            Sample::Fixed(v) if !v.is_finite() => Err(format!("{v} is not a finite number")),
            Sample::Fixed(_) => Ok(()),
            Sample::Random(Distribution::Uniform(a, b)) if !(finite(&[*a, *b]) && a <= b) => {
                Err(format!("uniform({a}, {b}) needs finite bounds with low <= high"))
            }
            Sample::Random(Distribution::Normal(m, s)) if !(finite(&[*m, *s]) && *s >= 0.0) => {
                Err(format!("normal({m}, {s}) needs a finite mean and a standard deviation >= 0"))
            }
            Sample::Random(Distribution::Choice(vs)) if vs.is_empty() || !finite(vs) => {
                Err("choice needs at least one finite value".into())
            }
            Sample::Random(_) => Ok(()),
            Sample::Shared(s) => Sample::Random(s.of.clone()).check(),
        }
    }

    /// The smallest and largest value a draw can take (before clipping, normal ±4σ).
    pub(crate) fn bounds(&self) -> [f32; 2] {
        match self {
            Sample::Shared(s) => Sample::Random(s.of.clone()).bounds(),
            Sample::Fixed(v) => [*v, *v],
            Sample::Random(Distribution::Uniform(a, b)) => [*a, *b],
            Sample::Random(Distribution::Normal(m, s)) => [m - 4.0 * s, m + 4.0 * s],
            Sample::Random(Distribution::Choice(vs)) => {
                vs.iter().fold([f32::INFINITY, f32::NEG_INFINITY], |[lo, hi], v| [lo.min(*v), hi.max(*v)])
            }
        }
    }
}

impl From<f32> for Sample {
    fn from(v: f32) -> Sample {
        Sample::Fixed(v)
    }
}

impl Distribution {
    fn draw(&self, rng: &mut MatchRng, limit: f32) -> f32 {
        self.map(self.underlying(rng), limit)
    }

    /// The draw underneath: a uniform in [0, 1) for `uniform` and `choice`, a standard normal for
    /// `normal` (the same use of the stream as a draw of its own).
    fn underlying(&self, rng: &mut MatchRng) -> f32 {
        match self {
            Distribution::Uniform(..) | Distribution::Choice(_) => rng.unit(),
            Distribution::Normal(..) => standard_normal(rng),
        }
    }

    /// The value of underlying draw `u` (see [`Distribution::underlying`]).
    fn map(&self, u: f32, limit: f32) -> f32 {
        match self {
            Distribution::Uniform(a, b) => a + (b - a) * u,
            Distribution::Normal(mean, std) => (mean + std * u).clamp(-limit, limit),
            Distribution::Choice(values) => values[((u * values.len() as f32) as usize).min(values.len() - 1)],
        }
    }
}

impl Region {
    /// Whether the point `(x, y)` lies in the region (edges included).
    pub fn contains(&self, x: f32, y: f32) -> bool {
        match self {
            Region::Rect { x: [x0, x1], y: [y0, y1] } => (*x0..=*x1).contains(&x) && (*y0..=*y1).contains(&y),
            Region::Circle { x: cx, y: cy, r } => (x - cx) * (x - cx) + (y - cy) * (y - cy) <= r * r,
        }
    }

    /// A point drawn uniformly in the region.
    pub(crate) fn draw(&self, rng: &mut MatchRng) -> [f32; 2] {
        match self {
            Region::Rect { x: [x0, x1], y: [y0, y1] } => [x0 + (x1 - x0) * rng.unit(), y0 + (y1 - y0) * rng.unit()],
            Region::Circle { x, y, r } => {
                // Uniform over the disc's area: radius ∝ √u.
                let radius = r * libm::sqrtf(rng.unit());
                let angle = std::f32::consts::TAU * rng.unit();
                [x + radius * libm::cosf(angle), y + radius * libm::sinf(angle)]
            }
        }
    }

    /// The region's bounding box `[[x_min, x_max], [y_min, y_max]]`.
    pub fn bounds(&self) -> [[f32; 2]; 2] {
        match self {
            Region::Rect { x, y } => [*x, *y],
            Region::Circle { x, y, r } => [[x - r, x + r], [y - r, y + r]],
        }
    }

    /// The region's centre.
    pub fn centre(&self) -> [f32; 2] {
        let [[x0, x1], [y0, y1]] = self.bounds();
        [0.5 * (x0 + x1), 0.5 * (y0 + y1)]
    }

    /// Checks parameters: finite, ordered bounds, a positive radius.
    pub(crate) fn check(&self) -> Result<(), String> {
        let [[x0, x1], [y0, y1]] = self.bounds();
        if ![x0, x1, y0, y1].iter().all(|v| v.is_finite()) {
            return Err("a region needs finite coordinates".into());
        }
        match self {
            Region::Rect { .. } if x0 > x1 || y0 > y1 => Err(format!("rect x {x0}..{x1}, y {y0}..{y1} is empty")),
            Region::Circle { r, .. } if *r <= 0.0 => Err(format!("circle radius {r} must be positive")),
            _ => Ok(()),
        }
    }
}

impl Spot {
    /// Draws a point.
    pub(crate) fn draw(&self, rng: &mut MatchRng, shared: &mut SharedDraws) -> [f32; 2] {
        match self {
            Spot::Point { x, y } => [x.draw(rng, PITCH_HALF_LENGTH, shared), y.draw(rng, PITCH_HALF_WIDTH, shared)],
            Spot::In(region) => region.draw(rng),
            Spot::OneOf(points) => points[pick(rng, points.len())],
            // Placed by `Scenario::draw`, which knows where the anchor was drawn.
            Spot::Relative(_) => self.nominal(),
        }
    }

    /// The point a reader sees without drawing (distribution or region centre, first choice).
    pub fn nominal(&self) -> [f32; 2] {
        match self {
            Spot::Point { x, y } => [x.nominal(), y.nominal()],
            Spot::In(region) => region.centre(),
            Spot::OneOf(points) => points.first().copied().unwrap_or([0.0, 0.0]),
            // Known only with the anchor's position: the entry's own x, y hold it.
            Spot::Relative(_) => [0.0, 0.0],
        }
    }

    /// The box every draw lies in, `[[x_min, x_max], [y_min, y_max]]` (normal draws clipped).
    pub fn bounds(&self) -> [[f32; 2]; 2] {
        match self {
            Spot::Point { x, y } => {
                let clip = |[lo, hi]: [f32; 2], limit: f32, normal: bool| {
                    if normal { [lo.max(-limit), hi.min(limit)] } else { [lo, hi] }
                };
                let is_normal = |s: &Sample| matches!(s.distribution(), Some(Distribution::Normal(..)));
                [clip(x.bounds(), PITCH_HALF_LENGTH, is_normal(x)), clip(y.bounds(), PITCH_HALF_WIDTH, is_normal(y))]
            }
            Spot::In(region) => region.bounds(),
            // A relative point is moved onto the pitch when it falls outside the lines.
            Spot::Relative(_) => [[-PITCH_HALF_LENGTH, PITCH_HALF_LENGTH], [-PITCH_HALF_WIDTH, PITCH_HALF_WIDTH]],
            Spot::OneOf(points) => points.iter().fold(
                [[f32::INFINITY, f32::NEG_INFINITY], [f32::INFINITY, f32::NEG_INFINITY]],
                |[[x0, x1], [y0, y1]], [x, y]| [[x0.min(*x), x1.max(*x)], [y0.min(*y), y1.max(*y)]],
            ),
        }
    }

    /// Checks parameters of every part.
    pub(crate) fn check(&self) -> Result<(), String> {
        match self {
            Spot::Point { x, y } => x.check().and_then(|()| y.check()),
            Spot::In(region) => region.check(),
            Spot::OneOf(points) if points.is_empty() => Err("one_of needs at least one point".into()),
            Spot::OneOf(points) if !points.iter().flatten().all(|v| v.is_finite()) => {
                Err("one_of needs finite points".into())
            }
            Spot::OneOf(_) => Ok(()),
            Spot::Relative(anchor) => anchor.check(),
        }
    }
}

/// An index in `0..n` (n ≥ 1), each equally likely.
fn pick(rng: &mut MatchRng, n: usize) -> usize {
    ((rng.unit() * n as f32) as usize).min(n - 1)
}

/// A standard normal draw (Box–Muller).
fn standard_normal(rng: &mut MatchRng) -> f32 {
    let u = 1.0 - rng.unit(); // in (0, 1]: the logarithm stays finite
    let v = rng.unit();
    libm::sqrtf(-2.0 * libm::logf(u)) * libm::cosf(std::f32::consts::TAU * v)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn draws_stay_in_their_support() {
        let mut rng = MatchRng::new(3, 0, true);
        let uniform = Sample::Random(Distribution::Uniform(-0.2, 0.1));
        let normal = Sample::Random(Distribution::Normal(0.4, 0.5));
        let choice = Sample::Random(Distribution::Choice(vec![0.1, 0.3]));
        let circle = Region::Circle { x: 0.5, y: 0.1, r: 0.05 };
        let mut seen = [false; 2];
        for _ in 0..2_000 {
            let u = uniform.draw(&mut rng, 1.0, &mut Vec::new());
            assert!((-0.2..=0.1).contains(&u));
            assert!(normal.draw(&mut rng, PITCH_HALF_WIDTH, &mut Vec::new()).abs() <= PITCH_HALF_WIDTH);
            let c = choice.draw(&mut rng, 1.0, &mut Vec::new());
            seen[usize::from(c > 0.2)] = true;
            let [x, y] = circle.draw(&mut rng);
            assert!(circle.contains(x, y) || libm::hypotf(x - 0.5, y - 0.1) < 0.050_001);
        }
        assert_eq!(seen, [true, true]);
    }

    #[test]
    fn normal_has_its_mean_and_spread() {
        let mut rng = MatchRng::new(9, 0, true);
        let n = 20_000;
        let draws: Vec<f32> = (0..n).map(|_| standard_normal(&mut rng)).collect();
        let mean = draws.iter().sum::<f32>() / n as f32;
        let var = draws.iter().map(|d| (d - mean) * (d - mean)).sum::<f32>() / n as f32;
        assert!(mean.abs() < 0.03, "mean {mean}");
        assert!((var - 1.0).abs() < 0.05, "variance {var}");
    }

    #[test]
    fn json_forms() {
        let spot: Spot = serde_json::from_str(r#"{"point": {"x": 0.12, "y": {"uniform": [-0.2, 0.2]}}}"#).unwrap();
        assert_eq!(spot, Spot::Point { x: Sample::Fixed(0.12), y: Sample::Random(Distribution::Uniform(-0.2, 0.2)) });
        let region: Spot = serde_json::from_str(r#"{"in": {"circle": {"x": 0.0, "y": 0.0, "r": 0.1}}}"#).unwrap();
        assert_eq!(region.nominal(), [0.0, 0.0]);
        assert!(serde_json::from_str::<Spot>(r#"{"in": {"square": 1}}"#).is_err());
    }

    #[test]
    fn checks_name_bad_parameters() {
        assert!(Sample::Random(Distribution::Uniform(0.3, 0.1)).check().is_err());
        assert!(Sample::Random(Distribution::Normal(0.0, -1.0)).check().is_err());
        assert!(Sample::Random(Distribution::Choice(vec![])).check().is_err());
        assert!(Region::Circle { x: 0.0, y: 0.0, r: 0.0 }.check().is_err());
        assert!(Spot::OneOf(vec![]).check().is_err());
    }
}
