rule fig3a_mean:
    """Figure 3a for the mean-behaviour model: pressure-outer diameter and mean stress-stretch."""
    input:
        code=PLOTS,
        states=rules.calibrate_mean.output.states,
        exact=rules.calibrate_mean.output.exact,
    output:
        pdf="figures/fig3a_mean.pdf",
        png="figures/fig3a_mean.png",
    conda:
        "../envs/sphgag.yaml"
    log:
        "logs/fig3a_mean.log",
    threads: 1
    resources:
        runtime=5,
        mem_mb=1000,
    script:
        "../scripts/fig3a_mean.py"


rule fig3b:
    """Figure 3b: transmural radial and circumferential stress of the mean model at 103, 145, 200 mmHg."""
    input:
        code=PLOTS,
        profiles=rules.transmural.output[0],
    output:
        pdf="figures/fig3b.pdf",
        png="figures/fig3b.png",
    conda:
        "../envs/sphgag.yaml"
    log:
        "logs/fig3b.log",
    threads: 1
    resources:
        runtime=5,
        mem_mb=1000,
    script:
        "../scripts/fig3b.py"


rule fig3:
    """Figure 3, complete: mean, passive and active models (pressure-diameter, stress-stretch, transmural)."""
    input:
        code=PLOTS,
        mean_states=rules.calibrate_mean.output.states,
        mean_exact=rules.calibrate_mean.output.exact,
        bilayer=rules.bilayer_table.output.table,
        passive_exact="results/calibration/bilayer_passive_exact_curve.csv",
        active_exact="results/calibration/bilayer_active_exact_curve.csv",
        profiles=rules.transmural.output[0],
    output:
        pdf="figures/fig3.pdf",
        png="figures/fig3.png",
    log:
        "logs/fig3.log",
    conda:
        "../envs/sphgag.yaml"
    threads: 1
    resources:
        runtime=5,
        mem_mb=1000,
    script:
        "../scripts/fig3.py"


rule fig1:
    """Figure 1: particle layout of the bi-layered model, the kernel, the layer composition."""
    input:
        code=PLOTS,
        particles=rules.homeostasis.output.particles,
    output:
        pdf="figures/fig1.pdf",
        png="figures/fig1.png",
    params:
        mass_fractions=config["bilayer"]["mass_fractions"],
        support_factor=config["numerics"]["kernel_support_factor"],
        dx=config["bilayer"]["dx_um"],
    log:
        "logs/fig1.log",
    conda:
        "../envs/sphgag.yaml"
    threads: 1
    resources:
        runtime=5,
        mem_mb=1000,
    script:
        "../scripts/fig1.py"


rule fig4:
    """Figure 4: the pools, and the tip radial and top hoop stress against GAG concentration."""
    input:
        code=PLOTS,
        tips=rules.tip_stress.output[0],
        particles=rules.homeostasis.output.particles,
    output:
        pdf="figures/fig4.pdf",
        png="figures/fig4.png",
    params:
        cases=config["swelling"]["cases"],
        probe_length=config["swelling"]["probe_length_um"],
    log:
        "logs/fig4.log",
    conda:
        "../envs/sphgag.yaml"
    threads: 1
    resources:
        runtime=5,
        mem_mb=1000,
    script:
        "../scripts/fig4.py"


rule claims:
    """The paper's claims (figures 3-7) against our numbers, from the CSV tables alone."""
    input:
        code=CLAIMS,
        mean=rules.calibrate_mean.output.states,
        bilayer=rules.bilayer_table.output.table,
        activation=rules.bilayer_table.output.activation,
        layers=rules.homeostasis.output.layers,
        transmural=rules.transmural.output[0],
        tips=rules.tip_stress.output[0],
        growth=rules.delamination_growth.output[0],
        delamination=rules.delamination_summary.output[0],
    output:
        table="results/claims.csv",
        markdown="figures/claims.md",
    params:
        cases=config["swelling"]["cases"],
        criteria=config["delamination"]["criteria"],
    log:
        "logs/claims.log",
    conda:
        "../envs/sphgag.yaml"
    script:
        "../scripts/claims.py"


rule swelling_convergence_figure:
    """Resolution study of the pool stresses: tip, top and pool volume change against concentration per dx."""
    input:
        code=PLOTS,
        table=rules.swelling_convergence.output[0],
    output:
        pdf="figures/swelling_convergence.pdf",
        png="figures/swelling_convergence.png",
    log:
        "logs/swelling_convergence_figure.log",
    conda:
        "../envs/sphgag.yaml"
    threads: 1
    resources:
        runtime=5,
        mem_mb=1000,
    script:
        "../scripts/swelling_convergence_figure.py"


# figures 5-7: the delamination runs (rule delaminate), one column or line style per onset criterion
DE_MEDIA_OUTER = config["bilayer"]["inner_radius_um"] + config["bilayer"]["media_thickness_um"]
# figure 5a shows the single pool at critical_stress_kPa if that is one of its sigma_cr, else at the nearest one
FIG5_SIGMA = min(DE["critical_stresses_kPa"], key=lambda s: abs(s - DE["critical_stress_kPa"]))
FIG6_CASES = ["low_separation", "high_separation"]
DE_SNAPSHOTS = "results/delamination/runs/{poolset}_{sigma}kPa_{criterion}_snapshots.npz"  # expanded over pool sets (outer) and criteria (inner)


rule fig5:
    """Figure 5: the single pool's growth (snapshots), its tip radial stress against pseudo-time for every sigma_cr."""
    input:
        code=PLOTS,
        growth=rules.delamination_growth.output[0],
        summary=rules.delamination_summary.output[0],
        snapshots=expand(DE_SNAPSHOTS, poolset=["single"], sigma=f"{FIG5_SIGMA:g}", criterion=DE["criteria"]),
    output:
        pdf="figures/fig5.pdf",
        png="figures/fig5.png",
    params:
        sigma=FIG5_SIGMA,
        criteria=DE["criteria"],
        media_outer=DE_MEDIA_OUTER,
    log:
        "logs/fig5.log",
    conda:
        "../envs/sphgag.yaml"
    threads: 1
    resources:
        runtime=5,
        mem_mb=1000,
    script:
        "../scripts/fig5.py"


rule fig6:
    """Figure 6: two pools at one radius, low and high separation: snapshots, interior and exterior growth."""
    input:
        code=PLOTS,
        growth=rules.delamination_growth.output[0],
        summary=rules.delamination_summary.output[0],
        snapshots=expand(DE_SNAPSHOTS, poolset=FIG6_CASES, sigma=f"{DE['critical_stress_kPa']:g}", criterion=DE["criteria"]),
    output:
        pdf="figures/fig6.pdf",
        png="figures/fig6.png",
    params:
        cases=FIG6_CASES,
        criteria=DE["criteria"],
        media_outer=DE_MEDIA_OUTER,
    log:
        "logs/fig6.log",
    conda:
        "../envs/sphgag.yaml"
    threads: 1
    resources:
        runtime=5,
        mem_mb=1000,
    script:
        "../scripts/fig6.py"


rule fig7:
    """Figure 7: two pools offset in radius: four snapshots per criterion, tip stress and growth."""
    input:
        code=PLOTS,
        growth=rules.delamination_growth.output[0],
        summary=rules.delamination_summary.output[0],
        snapshots=expand(DE_SNAPSHOTS, poolset=["radial_offset"], sigma=f"{DE['critical_stress_kPa']:g}", criterion=DE["criteria"]),
    output:
        pdf="figures/fig7.pdf",
        png="figures/fig7.png",
    params:
        case="radial_offset",
        sigma=DE["critical_stress_kPa"],
        criteria=DE["criteria"],
        media_outer=DE_MEDIA_OUTER,
    log:
        "logs/fig7.log",
    conda:
        "../envs/sphgag.yaml"
    threads: 1
    resources:
        runtime=5,
        mem_mb=1000,
    script:
        "../scripts/fig7.py"
