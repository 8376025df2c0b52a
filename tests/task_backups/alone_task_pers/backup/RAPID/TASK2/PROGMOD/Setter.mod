MODULE Setter
    ! Written for the test (issue 28): sets its shared bDone, not the robot's TASK PERS.
    PERS bool bDone := FALSE;

    PROC main()
        bDone := TRUE;
    ENDPROC
ENDMODULE
