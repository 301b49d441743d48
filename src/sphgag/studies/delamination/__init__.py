"""Delamination and coalescence: damage-driven growth of GAG pools (paper section 2.7, figures 5-7).

One module per concept:

* :mod:`.settings`: the settings of one run (:class:`Settings`) and its concentration ramp, and the registries of
  onset criteria and candidate rules they name;
* :mod:`.front`: the pools' front: damage candidates, connectivity of the converted particles, delaminated length,
  islands (:class:`Front`), and one damage pass of eq. (2.28) on a converged state (shared with the explicit
  procedure);
* :mod:`.growth`: the staggered protocol of one run, seeding, damage passes, snaps (:class:`GrowthRun`,
  :func:`grow`), and one point of the delamination map (:func:`map_point`);
* :mod:`.events`: the concentrations of a run's onset, runaway and merge, bisected between levels;
* :mod:`.tables`: a run's records and the tables of them: rows, summary and its statistics, labels, the
  delamination map's classes, the pool as a pressurised crack (:func:`griffith`);
* :mod:`.convergence`: the resolution study;
* :mod:`.runs`: the pipeline's runs of figures 5-7: one pool set grown and labelled (:func:`delaminate`), and its
  snapshots on disk, from which it can restart (:func:`save_snapshots`, :func:`load_snapshot`).

Each is imported from its module: this file runs no code, so that a job's code input is the modules it uses.
"""
