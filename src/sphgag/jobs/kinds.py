"""The kinds of job of the pipeline, by rule (:class:`sphgag.jobs.Kind`): each rule's run key, from which its
outputs, log, benchmark, provenance record and run name follow. The rules read them (``JOBS.<rule>``); the scripts
find theirs by their rule's name (:func:`sphgag.jobs.run`). A rule with no wildcards has no kind: its files are
named once in its rule, and its script names its run (``jobs.run(snakemake, name=...)``)."""

from __future__ import annotations

from . import Kind, register

# Calibration (figures 2-3): the passive or active bi-layered wall under pressure control
bilayer_pressure_diameter = Kind(
    "bilayer_pressure_diameter", "{model}", prefix="bilayer", log_path="logs/bilayer_pressure_diameter_{model}.log"
)

# Swelling (figure 4): one run per (charge law, pool model, wall model, pool, pressure)
swell = Kind("swell", "{law}/{pool}/{model}_{case}_{pressure}mmHg")
pool_stresses = Kind("pool_stresses", swell.key)

# The resolution study of figure 4: a run's pools under one charge law and pool model, in one wall, at one spacing
SC_POOLS = "{law}/{pool}"
swelling_convergence_dx = Kind(
    "swelling_convergence_dx",
    f"{SC_POOLS}/{{model}}_dx{{dx}}",
    prefix="swelling_convergence",
    stem="swelling_convergence",
)
swelling_convergence_stresses = Kind(
    "swelling_convergence_stresses",
    swelling_convergence_dx.key,
    log_path=f"logs/swelling_convergence/{SC_POOLS}/stresses_{{model}}_dx{{dx}}.log",
)

# The authors' explicit procedure (target paper_procedure): the start wall and equilibrium paths of each wall model,
# and the explicit runs ("procedure_..."; their logs in one folder) of figure 4's pools and of the delamination pool
# sets at each step factor
PROCEDURE_LOGS = "logs/paper_procedure"
procedure_start = Kind("procedure_start", "{model}", log_path=f"{PROCEDURE_LOGS}/{{model}}/start.log")
procedure_equilibrium = Kind("procedure_equilibrium", "{model}", log_path=f"{PROCEDURE_LOGS}/{{model}}/equilibrium.log")
EXPLICIT, DAMAGE = "{model}/{case}_x{factor}", "{poolset}/{sigma}kPa_x{factor}"
procedure_explicit = Kind("procedure_explicit", EXPLICIT, "procedure", log_path=f"{PROCEDURE_LOGS}/{EXPLICIT}.log")
procedure_delaminate = Kind("procedure_delaminate", DAMAGE, "procedure", log_path=f"{PROCEDURE_LOGS}/{DAMAGE}.log")

# The views of every run: a ParaView series of each swelling and delamination run ("{law}/{run}": any delamination
# run, of the paper's damage law or of one with a fracture energy), and an animation of each delamination run
ANY_DELAMINATION = "{law}/{run}"
paraview_swelling = Kind("paraview_swelling", swell.key, log_path=f"logs/paraview/swelling/{swell.key}.log")
paraview_delamination = Kind(
    "paraview_delamination", ANY_DELAMINATION, log_path=f"logs/paraview/delamination/{ANY_DELAMINATION}.log"
)
animation = Kind("animation", ANY_DELAMINATION)

# The numerical variants (target variants): one run per form of the hourglass control
variant = Kind("variant", "hourglass_{form}", log_path="logs/variants/hourglass_{form}.log")

register(
    bilayer_pressure_diameter,
    swelling_convergence_dx,
    swelling_convergence_stresses,
    procedure_start,
    procedure_equilibrium,
    procedure_explicit,
    procedure_delaminate,
    paraview_swelling,
    paraview_delamination,
    animation,
    variant,
)

register(swell, pool_stresses)
