MODULE DeadlockWaitDO
    ! Waits for an output that nothing ever sets.
    VAR bool done := FALSE;

    PROC main()
        SetDO do_ready, 0;
        WaitDO do_ready, 1;
        done := TRUE;
    ENDPROC
ENDMODULE
