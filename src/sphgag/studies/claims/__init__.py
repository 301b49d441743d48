"""The paper's claims (figures 3-7 and their text), evaluated from the pipeline's tables alone.

Each claim is one function of the :class:`.evidence.Evidence` (the tidy CSV tables and the configuration that made
them) that returns our number and whether the claim holds by a criterion written next to it. A claim that does not
hold is reported with our number; nothing here feeds back into a simulation. A claim whose data the configuration did
not produce (e.g. a reduced sweep) is reported as ``n/a``, or left out where the paper's figure itself needs the data
(C4-C5: two profiled pressures; C11-C12: both models).

One module per family of figures, each with the list of its claims:

* :mod:`.calibration`: figure 3, C1-C5 (:data:`.calibration.CALIBRATION`; no pool: ``charge_law`` "-");
* :mod:`.swelling`: figure 4, C6-C12 (:data:`.swelling.SWELLING`), and their verdicts across the resolution band;
* :mod:`.delamination`: figures 5-7, C13-C17, and the abstract's sensitivity study, C18;
* :mod:`.procedure`: the authors' explicit procedure (P1-P4) and settings (P5);
* :mod:`.evidence`: what they are judged on, and the helpers they share;
* :mod:`.verdicts`: the table, the pool claims evaluated once per charge law with the same criteria
  (:func:`.verdicts.evaluate`; column ``charge_law``): ``prescribed`` is the paper's model, ``conserved`` our
  deviation.

A new claim is a function and an entry of its family's list.

Most claims rest on the paper's figures, which the pipeline's default target (``all``) makes. A claim whose evidence
another target makes (C18: ``snakemake sensitivity``) is in the table whether or not that target has run: until it
has, its row says ``not run`` and names the command (:meth:`.evidence.Evidence.not_run`).
"""
