"""The kinds of job of the pipeline, by rule (:class:`sphgag.jobs.Kind`): each rule's run key, from which its
outputs, log, benchmark, provenance record and run name follow. The rules read them (``JOBS.<rule>``); the scripts
find theirs by their rule's name (:func:`sphgag.jobs.run`). A rule with no wildcards has no kind: its files are
named once in its rule, and its run is named after it."""

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

# Figure 4 against the authors' settings (target paper_settings): one run per base configuration (script, ours), the
# setting switched from it (none: the base itself) and wall model
PAPER_SETTINGS = "{base}/{setting}/{model}"
paper_settings_run = Kind("paper_settings_run", PAPER_SETTINGS, log_path=f"logs/paper_settings/{PAPER_SETTINGS}.log")

# The views of every run: a ParaView series of each swelling and delamination run ("{law}/{run}": any delamination
# run, of the configured damage law or of one with a fracture energy), and an animation of each delamination run
ANY_DELAMINATION = "{law}/{run}"
paraview_swelling = Kind("paraview_swelling", swell.key, log_path=f"logs/paraview/swelling/{swell.key}.log")
paraview_delamination = Kind(
    "paraview_delamination", ANY_DELAMINATION, log_path=f"logs/paraview/delamination/{ANY_DELAMINATION}.log"
)
animation = Kind("animation", ANY_DELAMINATION)

# The numerical variants (target variants): one run per form of the hourglass control
variant = Kind("variant", "hourglass_{form}", log_path="logs/variants/hourglass_{form}.log")


def _named(rule: str, key: str, name: str, **paths) -> Kind:
    """The kind of rule ``rule`` whose runs and files are named ``name`` (one computation run by two rules, or a
    rule named after its study)."""
    return Kind(rule, key, prefix=name, stem=name, **paths)


# Delamination (figures 5-7): one run per (charge law, pool set, sigma_cr, onset criterion), and one per G_c of the
# damage law with a fracture energy (the same computation: its runs, logs and records are named "delaminate")
delaminate = Kind("delaminate", "{law}/{poolset}_{sigma}kPa_{criterion}")
delaminate_fracture_energy = _named("delaminate_fracture_energy", delaminate.key + "_Gc{gc}", "delaminate")
# the resolution study: one charge law, particle spacing and onset criterion
delamination_convergence_dx = _named(
    "delamination_convergence_dx", "{law}/dx{dedx}_{criterion}", "delamination_convergence"
)

# The sensitivity study: a design per method, a batch of its samples per charge law, its indices and tables; the
# delamination map, one point per (charge law, angular extent, sigma_cr), logged with the study
sensitivity_design = _named("sensitivity_design", "{method}_design", "sensitivity")
screened_design = _named("screened_design", "{method}_design", "sensitivity")
sensitivity_batch = _named("sensitivity_batch", "{method}/{law}/batch{batch}", "sensitivity")
sensitivity_method = _named("sensitivity_method", "{method}_indices", "sensitivity")
sensitivity_tables = _named("sensitivity_tables", "aggregate", "sensitivity")
MAP_POINT = "{law}/{width}deg_{sigma}kPa"
delamination_map_point = _named(
    "delamination_map_point", MAP_POINT, "delamination_map", log_path=f"logs/sensitivity/map/{MAP_POINT}.log"
)

# The verification problems: a run per aspect ratio, crack half-length or pool model
verify_pool_ratio = _named("verify_pool_ratio", "ab{ratio}", "verify_pool")
verify_crack_length = _named("verify_crack_length", "a{length}", "verify_crack")
verify_circular_pool_model = _named("verify_circular_pool_model", "{model}", "verify_circular_pool")
verify_annulus_model = _named("verify_annulus_model", "{model}", "verify_annulus")
# the transmural profiles: one run per wall section (mean, bilayer), refinement level and lumen load
verify_profiles_wall = _named("verify_profiles_wall", "{section}_level{level}_{load}", "verify_profiles")

# every kind above, by its rule
register(*(value for value in tuple(globals().values()) if isinstance(value, Kind)))
