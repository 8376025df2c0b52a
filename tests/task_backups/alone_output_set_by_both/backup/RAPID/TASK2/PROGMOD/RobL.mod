MODULE RobL
    ! Written for the test (issue 28): the left arm pulses the right arm's output.
    PROC main()
        WaitTime 1;
        PulseDO doInPosR;
    ENDPROC
ENDMODULE
