MODULE RobL
    ! Written for the test (issue 28): the left arm only reads the right arm's output; no
    ! party left out sets it, so the right arm's wait for it is a true deadlock.
    PROC main()
        WaitDO doInPosR, 1;
    ENDPROC
ENDMODULE
