"""Time at equal quality: how long one renderer takes to reach the other's noise. For unbiased Monte
Carlo the relMSE falls as 1/samples, so time x relMSE is constant for a renderer on a scene, and
(rtpro's seconds x relMSE) / (Cycles' seconds x relMSE) is rtpro's time to reach Cycles' relMSE over
Cycles' time: noise per second, compared. Each run's pair (interleaved, each with a seed of its own)
gives one ratio; reported as the median with the spread. Valid while both estimators are unbiased and the
reference's own noise is small against theirs (a long render: REF_SPP >> SPP)."""
import statistics


def equal_quality_ratios(rtpro_seconds, rtpro_rel_mse, cycles_seconds, cycles_rel_mse):
    """Per-run ratios of rtpro's time to Cycles' at Cycles' relMSE."""
    return [(ts * rs) / (tc * rc) for ts, rs, tc, rc in zip(rtpro_seconds, rtpro_rel_mse, cycles_seconds,
                                                             cycles_rel_mse)]


def equal_quality_text(ratios):
    return (f"{statistics.median(ratios):.2f}x ({min(ratios):.2f}-{max(ratios):.2f}) of Cycles' time "
            f"at Cycles' relMSE")
