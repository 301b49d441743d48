rule fig3a_mean:
    """Figure 3a for the mean-behaviour model: pressure-outer diameter and mean stress-stretch."""
    input:
        states=rules.calibrate_mean.output.states,
        exact=rules.calibrate_mean.output.exact,
    output:
        pdf="figures/fig3a_mean.pdf",
        png="figures/fig3a_mean.png",
    conda:
        "../envs/sphgag.yaml"
    log:
        "logs/fig3a_mean.log",
    script:
        "../scripts/fig3a_mean.py"


rule fig3b:
    """Figure 3b: transmural radial and circumferential stress of the mean model at 103, 145, 200 mmHg."""
    input:
        profiles=rules.transmural.output[0],
    output:
        pdf="figures/fig3b.pdf",
        png="figures/fig3b.png",
    conda:
        "../envs/sphgag.yaml"
    log:
        "logs/fig3b.log",
    script:
        "../scripts/fig3b.py"
