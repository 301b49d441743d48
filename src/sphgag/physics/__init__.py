"""The physics without particles: constitutive laws of the wall and the GAG pools, damage laws and the closed forms
they are verified against (paper section 2).
"""
