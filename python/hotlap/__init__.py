"""hotlap: race-car tyre and brake thermal models, fits and minimum-time laps.

The compiled library (C++) does the work; this package gives it NumPy arrays and dicts. Units are
in every name: ``fz_N``, ``slip_angle_deg``, ``tread_temp_C``; summaries are dicts with the keys
of the command line's ``--json`` output (docs/json-output.md), channels are dicts of NumPy arrays
keyed by the CSV column names of the command line's files (docs/telemetry-csv.md).

    import hotlap
    car = hotlap.load_car("gen7")
    track = hotlap.load_track("darlington")
    lap = hotlap.qss_lap(car, track)
    print(lap["summary"]["lap_time_s"])

Bad input raises ``ValueError`` with the message the command line prints; a numerical failure
raises ``hotlap.NumericalError``. See docs/python.md.
"""

import numpy as _np

from ._hotlap import (  # noqa: F401  (the public API)
    Car,
    NumericalError,
    Track,
    TyreModel,
    __version__,
    convert_log,
    data_dir,
    default_cache_dir,
    fe,
    fit,
    load_car,
    load_track,
    load_tyre,
    log_info,
    observe,
    optimal_lap,
    override_keys,
    qss_lap,
    race,
    read_log,
    replay,
    stint,
    synth,
)
from . import _hotlap

__all__ = [
    "Car",
    "NumericalError",
    "Track",
    "TyreModel",
    "__version__",
    "convert_log",
    "data_dir",
    "default_cache_dir",
    "fe",
    "fit",
    "load_car",
    "load_track",
    "load_tyre",
    "log_info",
    "observe",
    "optimal_lap",
    "override_keys",
    "qss_lap",
    "race",
    "read_log",
    "replay",
    "stint",
    "synth",
    "tyre_forces",
]


def tyre_forces(model, **inputs):
    """Forces and moments of a tyre model at many operating points.

    Keyword inputs, each a number or an array (NumPy broadcasting applies), in the units of
    ``hotlap tyre eval``: ``fz_N`` (load, > 0), ``slip_angle_deg``, ``slip_ratio``, ``camber_deg``,
    ``speed_mps``, ``pressure_kPa`` (0: the model's nominal pressure), ``tread_temp_C``. Missing
    ones take ``hotlap tyre eval``'s defaults (4000 N, 0, 0, 0, 20 m/s, 0, 25 degC).

    Returns a dict of arrays of the broadcast shape: ``fx_N``, ``fy_N``, ``mz_Nm``, ``mx_Nm``,
    ``my_Nm`` (wheel axes, ISO signs: docs/tyre-forces.md). A Magic Formula evaluates several
    points at once (the library's batch path); the GIL is released meanwhile.
    """
    names = list(_hotlap._tyre_input_names)
    unknown = sorted(set(inputs) - set(names))
    if unknown:
        raise ValueError(
            "tyre_forces: unknown input(s) %s; the inputs are %s" % (", ".join(unknown), ", ".join(names))
        )
    values = [_np.asarray(inputs.get(name, default), dtype=_np.float64)
              for name, default in zip(names, _hotlap._tyre_input_defaults)]
    try:
        shape = _np.broadcast_shapes(*[v.shape for v in values])
    except ValueError as e:
        raise ValueError("tyre_forces: the inputs' shapes do not broadcast together: %s" % e) from None
    # One value stays one value (the library repeats it); arrays of the full shape go as they are
    # (no copy if already contiguous float64); others are broadcast out.
    flat = []
    for v in values:
        if v.size == 1:
            flat.append(v.reshape(1))
        elif v.shape == shape:
            flat.append(_np.ascontiguousarray(v).reshape(-1))
        else:
            flat.append(_np.ascontiguousarray(_np.broadcast_to(v, shape)).reshape(-1))
    out = _hotlap._tyre_forces(model, flat)
    return {key: value.reshape(shape) for key, value in out.items()}
