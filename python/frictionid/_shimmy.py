"""The towed wheel of ``frictionid shimmy`` (docs/physics.md §10)."""

from __future__ import annotations

from typing import TYPE_CHECKING, Any, Dict, Mapping, Optional, Tuple

from . import _data, _frictionid, _options

if TYPE_CHECKING:
    import pandas


def shimmy(
    model: str = "exact",
    pressure: Optional[str] = None,
    params: Optional[Mapping[str, float]] = None,
    *,
    contact: str = "circle",
    from_report: Optional[str] = None,
    N: float = 1000.0,
    R: float = 0.05,
    speed: float = 10.0,
    caster: float = 0.1,
    yaw_inertia: float = 1.0,
    yaw_stiffness: float = 1e4,
    yaw_damping: float = 0.0,
    lateral_mass: float = 10.0,
    lateral_stiffness: float = 1e5,
    lateral_damping: float = 0.0,
    lateral: str = "elastic",
    contact_law: str = "friction",
    integrator: str = "switching",
    psi0: float = 0.0,
    y0: float = 0.0,
    duration: float = 2.0,
    output_step: float = 0.0,
    tol: float = 1e-10,
    stick_threshold: float = 1e-5,
    cycle_tol: float = 1e-3,
    table_directions: int = 0,
) -> Tuple["pandas.DataFrame", Dict[str, Any]]:
    """A towed wheel or nose landing gear under the model's friction, as ``frictionid shimmy``
    (docs/physics.md §10): the king pin moves at ``speed`` V and sideways by y (strut
    ``lateral_mass``, ``lateral_stiffness``, ``lateral_damping``), the fork yaws by psi
    (``yaw_inertia``, ``yaw_stiffness``, ``yaw_damping``), the contact trails by ``caster``.

    Args:
        model, pressure, params, contact: the friction model, as for :func:`evaluate`
            (pressure None is ``hertz``); or ``from_report``, the report.json of a fit.
        N, R: normal load [N] and contact radius [m].
        lateral: ``elastic`` or ``rigid`` (y = 0); contact_law: ``friction`` or
            ``nonholonomic`` (Keldysh's no-slip u_y = 0); integrator: ``switching``
            (implicit RODAS steps where the friction is stiff, the default) or ``explicit``.
        psi0, y0: the start (velocities 0); duration [s]; output_step: rows at k*output_step
            from the dense output (0: every integrator step).
        tol, stick_threshold, cycle_tol, table_directions: as the command line's options
            (table_directions 4096 makes the exact model 20-50x faster, within ~1e-8).

    Returns:
        (trajectory, summary): a pandas DataFrame of t, y, y_dot, psi, psi_dot, u_y, T_y, M_z
        and a dict with the final state, the outcome (rest, limit_cycle with amplitude and
        frequency, growing, duration with a detail: holding, decaying, few_cycles or irregular)
        and the energy account.
    """
    options = dict(N=N, R=R, speed=speed, caster=caster, yaw_inertia=yaw_inertia,
                   yaw_stiffness=yaw_stiffness, yaw_damping=yaw_damping,
                   lateral_mass=lateral_mass, lateral_stiffness=lateral_stiffness,
                   lateral_damping=lateral_damping, psi0=psi0, y0=y0, duration=duration,
                   output_step=output_step, tol=tol, stick_threshold=stick_threshold,
                   cycle_tol=cycle_tol, table_directions=table_directions)
    text = dict(model=model, pressure="hertz" if pressure is None else pressure,
                contact=contact, lateral=lateral, contact_law=contact_law, integrator=integrator)
    if from_report is not None:
        text["from_report"] = str(from_report)
    out = dict(_frictionid.shimmy(_options.values("--param", params),
                                  {k: float(v) for k, v in options.items()}, text,
                                  pressure is not None))
    trajectory = _data.frame(out.pop("trajectory"))
    return trajectory, out
