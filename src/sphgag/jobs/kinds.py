"""The kinds of job of the pipeline, by rule (:class:`sphgag.jobs.Kind`): each rule's run key, from which its
outputs, log, benchmark, provenance record and run name follow. The rules read them (``JOBS.<rule>``); the scripts
find theirs by their rule's name (:func:`sphgag.jobs.run`)."""

from __future__ import annotations

from . import Kind, register

# Swelling (figure 4): one run per (charge law, pool model, wall model, pool, pressure)
swell = Kind("swell", "{law}/{pool}/{model}_{case}_{pressure}mmHg")
pool_stresses = Kind("pool_stresses", swell.key)

register(swell, pool_stresses)
