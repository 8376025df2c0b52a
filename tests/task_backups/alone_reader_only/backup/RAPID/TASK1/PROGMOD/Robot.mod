MODULE Robot
    ! Written for the test (issue 28): bDone is written here only; T_RX reads it. The
    ! TRUE written after the wait is a loaded write that ends it (awaited_from_outside: so
    ! no PC is assumed to write it), though it runs only once the wait has ended.
    PERS bool bDone := TRUE;

    PROC main()
        bDone := FALSE;
        WaitUntil bDone;
        bDone := TRUE;
    ENDPROC
ENDMODULE
