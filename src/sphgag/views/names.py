"""The file names of the paper's figures 4-7, drawn once per charge law: the paper's law keeps the paper's figure's name
(``fig4``), another law adds its own (``fig4_conserved``). No plotting here: the workflow's rules read it."""

from __future__ import annotations

from ..physics.donnan import CHARGE_LAWS

#: the figures drawn once per charge law (rules fig4-fig7)
LAW_FIGURES = ("fig4", "fig5", "fig6", "fig7")


def law_figure(stem: str, law: str) -> str:
    """The file stem of figure ``stem`` (``fig4``) drawn under charge law ``law``: ``stem`` for the paper's law,
    ``<stem>_<law>`` for another."""
    known = CHARGE_LAWS.get(law)
    return stem if known is not None and known.paper else f"{stem}_{law}"
