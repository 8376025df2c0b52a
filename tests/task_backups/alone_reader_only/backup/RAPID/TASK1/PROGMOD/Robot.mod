MODULE Robot
    ! Written for the test (issue 28): bDone is written here only; T_RX reads it.
    PERS bool bDone := TRUE;

    PROC main()
        bDone := FALSE;
        WaitUntil bDone;
    ENDPROC
ENDMODULE
