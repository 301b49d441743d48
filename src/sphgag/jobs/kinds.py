"""The kinds of job of the pipeline, by rule (:class:`sphgag.jobs.Kind`): each rule's run key, from which its
outputs, log, benchmark, provenance record and run name follow. The rules read them (``JOBS.<rule>``); the scripts
find theirs by their rule's name (:func:`sphgag.jobs.run`)."""

from __future__ import annotations

from . import Kind, register

# Swelling (figure 4): one run per (charge law, pool model, wall model, pool, pressure)
swell = Kind("swell", "{law}/{pool}/{model}_{case}_{pressure}mmHg")
pool_stresses = Kind("pool_stresses", swell.key)

register(swell, pool_stresses)


# Delamination (figures 5-7): one run per (charge law, pool set, sigma_cr, onset criterion), and one per G_c of the
# damage law with a fracture energy (the same computation: its runs, logs and records are named "delaminate")
delaminate = Kind("delaminate", "{law}/{poolset}_{sigma}kPa_{criterion}")
delaminate_fracture_energy = Kind("delaminate_fracture_energy", delaminate.key + "_Gc{gc}", prefix="delaminate")
# the resolution study: one charge law, particle spacing and onset criterion
delamination_convergence_dx = Kind(
    "delamination_convergence_dx", "{law}/dx{dedx}_{criterion}", prefix="delamination_convergence"
)

# The sensitivity study: a design per method, a batch of its samples per charge law, its indices and tables; the
# delamination map, one point per (charge law, angular extent, sigma_cr)
sensitivity_design = Kind("sensitivity_design", "{method}_design", prefix="sensitivity")
sobol_design = Kind("sobol_design", "sobol_design", prefix="sensitivity")
sensitivity_batch = Kind("sensitivity_batch", "{method}/{law}/batch{batch}", prefix="sensitivity")
sensitivity_method = Kind("sensitivity_method", "{method}_indices", prefix="sensitivity")
sensitivity_tables = Kind("sensitivity_tables", "aggregate", prefix="sensitivity")
delamination_map_point = Kind(
    "delamination_map_point", "{law}/{width}deg_{sigma}kPa", prefix="delamination_map", logs="sensitivity/map"
)

# The verification problems: a run per aspect ratio, crack half-length or pool model
verify_pool_ratio = Kind("verify_pool_ratio", "ab{ratio}", prefix="verify_pool")
verify_crack_length = Kind("verify_crack_length", "a{length}", prefix="verify_crack")
verify_circular_pool_model = Kind("verify_circular_pool_model", "{model}", prefix="verify_circular_pool")
verify_annulus_model = Kind("verify_annulus_model", "{model}", prefix="verify_annulus")

register(
    delaminate,
    delaminate_fracture_energy,
    delamination_convergence_dx,
    sensitivity_design,
    sobol_design,
    sensitivity_batch,
    sensitivity_method,
    sensitivity_tables,
    delamination_map_point,
    verify_pool_ratio,
    verify_crack_length,
    verify_circular_pool_model,
    verify_annulus_model,
)
