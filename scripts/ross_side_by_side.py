"""Side-by-side: Stribeck's plain journal bearing against ROSS's finite-difference one.

One L/D = 1 plain journal bearing (D = 0.1 m, L = 0.1 m, C = 0.1 mm, mu = 0.02 Pa s constant,
3000 rpm) at a given eccentricity ratio (0.8 and 0.95), both tools computing the film force and
the stiffness and damping:

- ROSS (`ross-rotordynamics`, class `ross.bearings.fluid_flow.FluidFlow` + its
  `calculate_stiffness_and_damping_coefficients`, the model behind `BearingFluidFlow`), timed
  in-process with time.perf_counter at a few grids (nz x ntheta);
- Stribeck: `stribeck run /v1/journal-bearings/plain` at `fidelity: standard` (dynamics on by
  default: K, C and the whirl threshold), timed by the response's `solver.elapsed_ms` (the
  calculation, without process start); the subprocess's wall time is printed beside it.

Runs are interleaved (each round: Stribeck, then each ROSS grid, at each eccentricity).
Accuracy is against Stribeck at `{"grid": [384, 48]}` (load Richardson-extrapolated from the
half mesh) with the same film model: ROSS's FluidFlow clips the full film's negative pressures
(Gumbel's half-Sommerfeld film), so it is measured against Stribeck's `half_sommerfeld` film, and
Stribeck runs both that and its default Reynolds-condition film. Errors are in the Sommerfeld number S = mu N_s L D (R/C)^2 / W and the direct stiffness along
the load k_xx C / W. ROSS's K is in its own x-y frame (load along -y, rotation counter-clockwise);
it is rotated into Stribeck's (x along the load, y 90 deg ahead in the direction of rotation)
using ROSS's own film force.

ROSS is not a dependency of the service; this script is optional tooling. Run with

    python3 -m venv target/ross-venv && target/ross-venv/bin/pip install ross-rotordynamics 'plotly<6'
    STRIBECK=target/release/stribeck target/ross-venv/bin/python scripts/ross_side_by_side.py

(`plotly<6`: ROSS 2.3.0's plot theme fails to import with plotly 6+.)
"""

import json
import os
import statistics
import subprocess
import sys
import time

import numpy as np

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
STRIBECK = os.environ.get("STRIBECK", os.path.join(REPO, "target/release/stribeck"))

D, L, C, MU, RPM = 0.1, 0.1, 1e-4, 0.02, 3000.0
N_S = RPM / 60.0  # rev/s
OMEGA = 2 * np.pi * N_S
R = D / 2
EPSILONS = [0.8, 0.95]
STRIBECK_REPS = 5
ROSS_GRIDS = [((11, 101), 5), ((21, 201), 3), ((31, 301), 1), ((51, 501), 1)]  # (nz, ntheta), repetitions


def import_ross():
    """Import ROSS with its start-up chatter (REFPROP, CoolProp) sent to /dev/null."""
    saved = [os.dup(1), os.dup(2)]
    null = os.open(os.devnull, os.O_WRONLY)
    os.dup2(null, 1)
    os.dup2(null, 2)
    try:
        from ross.bearings.fluid_flow import FluidFlow
        from ross.bearings.fluid_flow_coefficients import (
            calculate_oil_film_force,
            calculate_stiffness_and_damping_coefficients,
        )
        from ross.bearings.fluid_flow_geometry import calculate_attitude_angle
        import ross
    finally:
        sys.stdout.flush()
        os.dup2(saved[0], 1)
        os.dup2(saved[1], 2)
        os.close(null)
    return ross.__version__, FluidFlow, calculate_oil_film_force, calculate_stiffness_and_damping_coefficients, calculate_attitude_angle


ROSS_VERSION, FluidFlow, film_force, stiffness_damping, short_attitude = import_ross()


def sommerfeld(load_n):
    return MU * N_S * L * D / load_n * (R / C) ** 2


MODELS = ["reynolds", "half_sommerfeld"]


def stribeck(eps, fidelity, model):
    """One Stribeck request with cavitation model `model`: (S, k_xx C/W, elapsed ms, wall ms)."""
    request = {
        "geometry": {"diameter_m": D, "length_m": L, "radial_clearance_m": C},
        "speed_rpm": RPM,
        "lubricant": {"viscosity_pa_s": MU},
        "eccentricity_ratio": eps,
        "fidelity": fidelity,
        "effects": {"cavitation": model},
    }
    t0 = time.perf_counter()
    out = subprocess.run(
        [STRIBECK, "run", "/v1/journal-bearings/plain"],
        input=json.dumps(request), capture_output=True, text=True, check=True,
    )
    wall_ms = (time.perf_counter() - t0) * 1e3
    body = json.loads(out.stdout)
    result = body["result"]
    kxx = result["dynamic_coefficients"]["stiffness_dimensionless"][0]
    return result["sommerfeld_number"], kxx, body["solver"]["elapsed_ms"], wall_ms


def ross(eps, nz, ntheta):
    """ROSS FluidFlow at eccentricity eps with K and C: (S, k_xx C/W along the load, ms)."""
    t0 = time.perf_counter()
    flow = FluidFlow(
        nz, ntheta, L, OMEGA, 0.0, 0.0, R, R + C, MU, 870.0,
        eccentricity=eps * C, attitude_angle=short_attitude(eps),  # ROSS needs an angle; any works
    )
    _, _, fx, fy = film_force(flow, force_type="numerical")
    k, _c = stiffness_damping(flow)
    elapsed_ms = (time.perf_counter() - t0) * 1e3
    load = np.hypot(fx, fy)
    # Stribeck's frame: x along the load (opposite the film force), y 90 deg ahead of it in the
    # direction of rotation (counter-clockwise in ROSS's x-y plane).
    ex = -np.array([fx, fy]) / load
    ey = np.array([-ex[1], ex[0]])
    K = np.array([[k[0], k[1]], [k[2], k[3]]])
    kxx_load = ex @ K @ ex
    return sommerfeld(load), kxx_load * C / load, elapsed_ms


def rel(value, ref):
    return (value - ref) / ref * 100.0


def main():
    print(f"ROSS {ROSS_VERSION}, Stribeck {STRIBECK}", flush=True)
    reference = {}
    for eps in EPSILONS:
        for model in MODELS:
            s, kxx, ms, _ = stribeck(eps, {"grid": [384, 48]}, model)
            reference[(eps, model)] = (s, kxx)
            print(f"reference eps={eps} {model}: S={s:.6g} k_xx={kxx:.6g} ({ms:.0f} ms)", flush=True)

    runs = {}  # (eps, tool, settings) -> list of (S, kxx, ms, wall ms or None)
    rounds = max([STRIBECK_REPS] + [reps for _, reps in ROSS_GRIDS])
    for r in range(rounds):
        for eps in EPSILONS:
            if r < STRIBECK_REPS:
                for model in MODELS:
                    runs.setdefault((eps, "Stribeck", f"standard (96 x 12), {model}"), []).append(
                        stribeck(eps, "standard", model))
            for (nz, nt), reps in ROSS_GRIDS:
                if r < reps:
                    s, kxx, ms = ross(eps, nz, nt)
                    runs.setdefault((eps, "ROSS", f"nz x ntheta = {nz} x {nt}"), []).append((s, kxx, ms, None))
        print(f"round {r + 1}/{rounds} done", flush=True)

    print()
    print("| ε | tool | settings | median time | S error vs reference | k_xx error vs reference | ROSS / Stribeck |")
    print("|---|---|---|---|---|---|---|")
    for eps in EPSILONS:
        base = statistics.median(
            x[2] for x in runs[(eps, "Stribeck", "standard (96 x 12), half_sommerfeld")])
        for (e, tool, settings), xs in runs.items():
            if e != eps:
                continue
            # Each against the reference of its own film model; ROSS's is the half film.
            model = "reynolds" if settings.endswith("reynolds") else "half_sommerfeld"
            s_ref, k_ref = reference[(eps, model)]
            t = statistics.median(x[2] for x in xs)
            if tool == "Stribeck":
                wall = statistics.median(x[3] for x in xs)
                time_cell = f"{t:.2f} ms (process wall {wall:.1f} ms)"
                ratio = "1"
            else:
                time_cell = f"{t:.0f} ms"
                ratio = f"{t / base:.0f}×"
            s, kxx = xs[-1][0], xs[-1][1]
            print(f"| {eps} | {tool} | {settings}, n = {len(xs)} | {time_cell} | "
                  f"{rel(s, s_ref):+.2f} % | {rel(kxx, k_ref):+.2f} % | {ratio} |")


if __name__ == "__main__":
    main()
