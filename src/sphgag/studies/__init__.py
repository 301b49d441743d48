"""The paper's artery and what is done with it: loading protocols, swelling, delamination, verification problems,
resolution and sensitivity studies, and the paper's claims (paper sections 2.5-3).
"""
