"""A sensitivity method of one file: plain random sampling, each input ranked by its Spearman rank correlation with
the output."""

import numpy as np
import pandas as pd

from sphgag.studies.sensitivity import SENSITIVITY_METHODS, SensitivityMethod, sample_counts

REGISTRY = SENSITIVITY_METHODS


class RankCorrelation(SensitivityMethod):
    """``samples`` uniform random samples of every input; ``rho``: each input's Spearman rank correlation with the
    output over the samples that have one (no interval)."""

    def size(self, k, samples, **design):
        return samples

    def design(self, problem, samples, seed, screening=None):
        u = np.random.default_rng(seed).random((samples, len(problem.names)))
        return problem.design(np.add(problem.low, u * np.subtract(problem.high, problem.low)))

    def indices(self, problem, design, y, failed, **indices):
        y, failed = np.asarray(y, float), np.asarray(failed, bool)
        used = np.isfinite(y)
        ranks = design.loc[used, list(problem.names)].rank()
        rho = ranks.corrwith(pd.Series(y[used], index=ranks.index).rank())
        return self.rows(problem, dict(rho=[(r, np.nan) for r in rho]), sample_counts(y, used, failed))


VARIANT = RankCorrelation("rank_correlation", "Spearman (a test)", ("samples", "seed"), ())
