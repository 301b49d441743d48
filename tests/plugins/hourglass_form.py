"""An hourglass form of one file: no hourglass control at all (neither eq. 2.14's pair forces nor a stiffness)."""

from dataclasses import dataclass

import numpy as np

from sphgag.engine.forces import HOURGLASS_FORMS, HourglassForm

REGISTRY = HOURGLASS_FORMS


@dataclass(frozen=True)
class NoForm(HourglassForm):
    """Zero pair coefficients and no stiffness: the wall's zero-energy modes go unchecked."""

    def contribute(self, model, ah, sh, hgc):
        return np.zeros_like(hgc), None


VARIANT = NoForm("none", "no hourglass control (a test)")
