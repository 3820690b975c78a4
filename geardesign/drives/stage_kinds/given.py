"""The bought unit (:class:`~geardesign.drives.stages.GivenStage`) as a stage kind: one fixed ratio,
checked against its rated output torque in a batch; drawn as a box."""
from __future__ import annotations

from ..stages import EFFICIENCY_RANGE, GIVEN_RATIO_RANGE, GivenStage
from .base import Batch, StageKind

__all__ = ["GivenKind"]


class GivenKind(StageKind):
    name = "given"
    stage_class = GivenStage
    colour = "#d9d9d9"

    def batch(self, stage, designs) -> Batch:
        return Batch(margins=stage.margins(designs.torque_out_nm))

    def analyse(self, stage, flow, objective: str) -> dict:
        """A bought unit's margins (its rated output torque) and summary."""
        return dict(stage=stage, margins={k: float(v) for k, v in stage.margins(flow.torque_out_nm).items()},
                    summary=dict(name=stage.name, kind="given", ratio=stage.ratio, efficiency=stage.efficiency))

    def scene_keys(self) -> dict:
        return {"ratio": dict(kind="float", required=True, lo=GIVEN_RATIO_RANGE[0], hi=GIVEN_RATIO_RANGE[1]),
                "efficiency": dict(kind="float", required=True, lo=EFFICIENCY_RANGE[0], hi=EFFICIENCY_RANGE[1],
                                   lo_open=True),
                "rated_output_torque_nm": dict(kind="float", lo=0.0, lo_open=True)}
