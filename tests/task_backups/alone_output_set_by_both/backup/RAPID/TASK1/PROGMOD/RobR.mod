MODULE RobR
    ! Written for the test (issue 28, the YuMi cell of the survey): the right arm clears
    ! its "in position" output, waits until the left arm (not loaded) pulses it, and pulses
    ! it itself at the end of its cycle. The loaded code sets the output too, but the left
    ! arm's pulse may come at any try: the wait ends, no deadlock.
    VAR num cycles := 0;

    PROC main()
        SetDO doInPosR, 0;
        WaitDO doInPosR, 1;
        cycles := cycles + 1;
        PulseDO doInPosR;
    ENDPROC
ENDMODULE
