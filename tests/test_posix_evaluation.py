"""The paper's evaluation (scripts/run-evaluation.sh) as a test: mROS ->
rospy/roscpp and rospy/roscpp -> mROS with PersonalData, values checked."""

import posix_evaluation


def test_paper_evaluation_delivers_personal_data_both_ways(ros_workspace, mros_firmware):
    directions = posix_evaluation.run(ros_workspace, mros_firmware, count=3)
    assert [d.title for d in directions] == [
        'mROS -> rospy listener', 'mROS -> roscpp listener',
        'rospy talker -> mROS', 'roscpp talker -> mROS']
    for direction in directions:
        assert direction.problem is None, direction.summary()
        assert len(direction.received) == 3
