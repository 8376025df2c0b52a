MODULE DeadlockWaitDIEnv
    ! Waits for di_go, a free input: it may come.
    VAR bool started := FALSE;

    PROC main()
        WaitDI di_go, 1;
        started := TRUE;
    ENDPROC
ENDMODULE
