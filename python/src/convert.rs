//! Raw observations as GRF's dict of numpy arrays (docs/grf-compatibility.md#raw-observation): float64
//! positions, int64 roles, bool flags, uint8 sticky actions.

use numpy::{PyArray1, PyArray2, PyArrayMethods};
use pyo3::prelude::*;
use pyo3::types::PyDict;
use touchline_engine::RawObservation;

fn pairs<'py>(py: Python<'py>, rows: &[[f32; 2]]) -> PyResult<Bound<'py, PyArray2<f64>>> {
    let flat: Vec<f64> = rows.iter().flat_map(|r| [f64::from(r[0]), f64::from(r[1])]).collect();
    PyArray1::from_vec(py, flat).reshape([rows.len(), 2])
}

fn floats<'py>(py: Python<'py>, values: &[f32]) -> Bound<'py, PyArray1<f64>> {
    PyArray1::from_iter(py, values.iter().map(|v| f64::from(*v)))
}

/// One controller's raw observation as a dict with GRF's keys.
pub(crate) fn raw_to_dict<'py>(py: Python<'py>, o: &RawObservation) -> PyResult<Bound<'py, PyDict>> {
    let d = PyDict::new(py);
    d.set_item("ball", floats(py, &o.ball))?;
    d.set_item("ball_direction", floats(py, &o.ball_direction))?;
    d.set_item("ball_rotation", floats(py, &o.ball_rotation))?;
    d.set_item("ball_owned_team", o.ball_owned_team)?;
    d.set_item("ball_owned_player", o.ball_owned_player)?;
    for (prefix, pos, dir, tired, card, active, roles) in [
        (
            "left_team",
            &o.left_team,
            &o.left_team_direction,
            &o.left_team_tired_factor,
            &o.left_team_yellow_card,
            &o.left_team_active,
            &o.left_team_roles,
        ),
        (
            "right_team",
            &o.right_team,
            &o.right_team_direction,
            &o.right_team_tired_factor,
            &o.right_team_yellow_card,
            &o.right_team_active,
            &o.right_team_roles,
        ),
    ] {
        d.set_item(prefix, pairs(py, pos)?)?;
        d.set_item(format!("{prefix}_direction"), pairs(py, dir)?)?;
        d.set_item(format!("{prefix}_tired_factor"), floats(py, tired))?;
        d.set_item(format!("{prefix}_yellow_card"), PyArray1::from_slice(py, card))?;
        d.set_item(format!("{prefix}_active"), PyArray1::from_slice(py, active))?;
        d.set_item(format!("{prefix}_roles"), PyArray1::from_iter(py, roles.iter().map(|r| i64::from(*r))))?;
    }
    d.set_item("score", vec![o.score[0], o.score[1]])?;
    d.set_item("steps_left", o.steps_left)?;
    d.set_item("game_mode", o.game_mode as u8)?;
    d.set_item("active", o.active)?;
    d.set_item("designated", o.designated)?;
    d.set_item("sticky_actions", PyArray1::from_slice(py, &o.sticky_actions))?;
    Ok(d)
}
