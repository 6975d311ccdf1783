//! Raw observations as GRF's dict of numpy arrays (docs/grf-compatibility.md#raw-observation): float64
//! positions, int64 roles, bool flags, uint8 sticky actions.

use numpy::ndarray::ArrayView2;
use numpy::{PyArray1, PyArray2};
use pyo3::intern;
use pyo3::prelude::*;
use pyo3::sync::PyOnceLock;
use pyo3::types::{PyDict, PyString};
use touchline_engine::RawObservation;

/// A new dict already holding `keys` (each `None`), copied from a template made once: the values
/// set afterwards replace entries in place, where a dict built up from empty is resized three
/// times on the way to GRF's 23 keys (a dict is made for every observation and step).
pub(crate) fn dict_with_keys<'py>(
    py: Python<'py>,
    template: &'static PyOnceLock<Py<PyDict>>,
    keys: &[&'static str],
) -> PyResult<Bound<'py, PyDict>> {
    let template = template.get_or_try_init(py, || -> PyResult<Py<PyDict>> {
        let d = PyDict::new(py);
        for key in keys {
            d.set_item(PyString::intern(py, key), py.None())?;
        }
        Ok(d.unbind())
    })?;
    template.bind(py).copy()
}

/// The raw observation's keys, in GRF's order.
const RAW_KEYS: [&str; 23] = [
    "ball",
    "ball_direction",
    "ball_rotation",
    "ball_owned_team",
    "ball_owned_player",
    "left_team",
    "left_team_direction",
    "left_team_tired_factor",
    "left_team_yellow_card",
    "left_team_active",
    "left_team_roles",
    "right_team",
    "right_team_direction",
    "right_team_tired_factor",
    "right_team_yellow_card",
    "right_team_active",
    "right_team_roles",
    "score",
    "steps_left",
    "game_mode",
    "active",
    "designated",
    "sticky_actions",
];
static RAW_TEMPLATE: PyOnceLock<Py<PyDict>> = PyOnceLock::new();

/// Most rows `pairs` is given: a full team.
const MAX_ROWS: usize = touchline_engine::MAX_PLAYERS_PER_TEAM;

fn pairs<'py>(py: Python<'py>, rows: &[[f32; 2]]) -> PyResult<Bound<'py, PyArray2<f64>>> {
    // Widened on the stack and copied once into the new array: no intermediate heap buffer and
    // no reshaped second array object (this dict is built every step of a `raw` env).
    let mut flat = [0.0f64; 2 * MAX_ROWS];
    let n = rows.len().min(MAX_ROWS);
    for (out, row) in flat.chunks_exact_mut(2).zip(&rows[..n]) {
        out[0] = f64::from(row[0]);
        out[1] = f64::from(row[1]);
    }
    let view = ArrayView2::from_shape((n, 2), &flat[..2 * n])
        .map_err(|e| pyo3::exceptions::PyValueError::new_err(e.to_string()))?;
    Ok(PyArray2::from_array(py, &view))
}

/// Widens `values` on the stack and copies them once into a new array: `PyArray1::from_iter`
/// collects into a `Vec` that the array then borrows through a second Python object, two
/// allocations and an object more per array, seven arrays per observation.
fn widened<'py, T: numpy::Element + Copy + Default, const N: usize>(
    py: Python<'py>,
    values: impl Iterator<Item = T>,
) -> Bound<'py, PyArray1<T>> {
    let mut buffer = [T::default(); N];
    let mut n = 0;
    for (slot, value) in buffer.iter_mut().zip(values) {
        *slot = value;
        n += 1;
    }
    PyArray1::from_slice(py, &buffer[..n])
}

fn floats<'py>(py: Python<'py>, values: &[f32]) -> Bound<'py, PyArray1<f64>> {
    widened::<f64, MAX_ROWS>(py, values.iter().map(|v| f64::from(*v)))
}

/// One controller's raw observation as a dict with GRF's keys.
pub(crate) fn raw_to_dict<'py>(py: Python<'py>, o: &RawObservation) -> PyResult<Bound<'py, PyDict>> {
    let d = dict_with_keys(py, &RAW_TEMPLATE, &RAW_KEYS)?;
    d.set_item(intern!(py, "ball"), floats(py, &o.ball))?;
    d.set_item(intern!(py, "ball_direction"), floats(py, &o.ball_direction))?;
    d.set_item(intern!(py, "ball_rotation"), floats(py, &o.ball_rotation))?;
    d.set_item(intern!(py, "ball_owned_team"), o.ball_owned_team)?;
    d.set_item(intern!(py, "ball_owned_player"), o.ball_owned_player)?;
    let teams = [
        (
            [
                intern!(py, "left_team"),
                intern!(py, "left_team_direction"),
                intern!(py, "left_team_tired_factor"),
                intern!(py, "left_team_yellow_card"),
                intern!(py, "left_team_active"),
                intern!(py, "left_team_roles"),
            ],
            (&o.left_team, &o.left_team_direction, &o.left_team_tired_factor),
            (&o.left_team_yellow_card, &o.left_team_active, &o.left_team_roles),
        ),
        (
            [
                intern!(py, "right_team"),
                intern!(py, "right_team_direction"),
                intern!(py, "right_team_tired_factor"),
                intern!(py, "right_team_yellow_card"),
                intern!(py, "right_team_active"),
                intern!(py, "right_team_roles"),
            ],
            (&o.right_team, &o.right_team_direction, &o.right_team_tired_factor),
            (&o.right_team_yellow_card, &o.right_team_active, &o.right_team_roles),
        ),
    ];
    for ([k_pos, k_dir, k_tired, k_card, k_active, k_roles], (pos, dir, tired), (card, active, roles)) in teams {
        d.set_item(k_pos, pairs(py, pos)?)?;
        d.set_item(k_dir, pairs(py, dir)?)?;
        d.set_item(k_tired, floats(py, tired))?;
        d.set_item(k_card, PyArray1::from_slice(py, card))?;
        d.set_item(k_active, PyArray1::from_slice(py, active))?;
        d.set_item(k_roles, widened::<i64, MAX_ROWS>(py, roles.iter().map(|r| i64::from(*r))))?;
    }
    d.set_item(intern!(py, "score"), vec![o.score[0], o.score[1]])?;
    d.set_item(intern!(py, "steps_left"), o.steps_left)?;
    d.set_item(intern!(py, "game_mode"), o.game_mode as u8)?;
    d.set_item(intern!(py, "active"), o.active)?;
    d.set_item(intern!(py, "designated"), o.designated)?;
    d.set_item(intern!(py, "sticky_actions"), PyArray1::from_slice(py, &o.sticky_actions))?;
    Ok(d)
}
