MODULE Robot
    ! Written for the test (issue 28): a TASK PERS is this task's own, whatever T_RX writes.
    TASK PERS bool bDone := TRUE;

    PROC main()
        bDone := FALSE;
        WaitUntil bDone;
    ENDPROC
ENDMODULE
