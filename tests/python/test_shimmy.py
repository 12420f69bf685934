"""frictionid.shimmy: the towed wheel of docs/physics.md §10, as the command line runs it."""

import json

import pytest

import frictionid

WHEEL = dict(N=1000, R=0.05, caster=0.1, yaw_inertia=0.5, yaw_stiffness=2000, yaw_damping=1,
             lateral_mass=20, lateral_stiffness=2e5, lateral_damping=50, psi0=0.05)


def test_shimmy_returns_the_trajectory_and_the_command_lines_summary(run_cli):
    traj, summary = frictionid.shimmy("corrected", "uniform", {"f": 0.8}, speed=15,
                                      duration=0.3, output_step=0.005, **WHEEL)
    args = ["shimmy", "--model", "corrected", "--pressure", "uniform", "--param", "f=0.8",
            "--speed", "15", "--duration", "0.3", "--output-step", "0.005"]
    for k, v in WHEEL.items():
        args += ["--" + k.replace("_", "-"), str(v)]
    cli = json.loads(run_cli(*args).stdout)
    assert summary["final"] == cli["final"]
    assert summary["outcome"] == cli["outcome"]
    assert summary["energy"] == cli["energy"]
    assert list(traj.columns) == ["t", "y", "y_dot", "psi", "psi_dot", "u_y", "T_y", "M_z"]
    assert len(traj) == 61
    assert traj.t.iloc[10] == 10 * 0.005
    assert traj.psi.iloc[0] == pytest.approx(0.05)
    e = summary["energy"]
    assert e["final"] - e["initial"] == pytest.approx(
        e["contact_work"] - e["damping_dissipated"], abs=1e-8 * e["friction_dissipated"])
    assert e["friction_dissipated"] >= 0


def test_shimmy_rejects_bad_input():
    with pytest.raises(frictionid.InputError, match="--yaw-inertia"):
        frictionid.shimmy("corrected", "uniform", {"f": 0.8}, yaw_inertia=0)
    with pytest.raises(frictionid.InputError, match="--lateral"):
        frictionid.shimmy("corrected", "uniform", {"f": 0.8}, lateral="floppy")
    with pytest.raises(frictionid.InputError, match="--integrator"):
        frictionid.shimmy("corrected", "uniform", {"f": 0.8}, integrator="implicit")


def test_shimmy_names_its_integrator_and_counts_the_implicit_steps(run_cli):
    wheel = dict(WHEEL, N=2000)
    _, explicit = frictionid.shimmy("corrected", "uniform", {"f": 0.8}, speed=3, duration=0.2,
                                    integrator="explicit", **wheel)
    _, switching = frictionid.shimmy("corrected", "uniform", {"f": 0.8}, speed=3, duration=0.2,
                                     **wheel)
    assert explicit["integrator"] == "explicit" and explicit["implicit_steps"] == 0
    assert switching["integrator"] == "switching" and switching["implicit_steps"] > 0


def test_shimmy_with_a_direction_table_follows_the_model():
    kw = dict(WHEEL, speed=20, duration=0.2, output_step=0.01)
    plain, first = frictionid.shimmy("exact", "hertz", {"f": 0.8}, **kw)
    tabled, summary = frictionid.shimmy("exact", "hertz", {"f": 0.8}, table_directions=4096, **kw)
    assert summary["table_directions"] == 4096
    # Through the first slip phase (after it, events amplify differences to the stick threshold).
    slip = plain.t < first["first_switch"]
    assert slip.sum() > 3
    assert (plain.psi[slip] - tabled.psi[slip]).abs().max() < 1e-8 * 0.05
