MODULE DeadlockWaitDIEnv
    ! Waits for di_go, which the environment drives but never sets.
    VAR bool started := FALSE;

    PROC main()
        WaitDI di_go, 1;
        started := TRUE;
    ENDPROC
ENDMODULE
