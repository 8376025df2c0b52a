MODULE DeadlockWait
    ! The conveyor waits for its own output, which the branch before cleared: it waits
    ! forever once the operator answers 2.
    VAR num answer := 0;

    PROC main()
        SetDO do_ready, 1;
        TPReadNum answer, "Mode?";
        IF answer = 2 SetDO do_ready, 0;
        WaitDO do_ready, 1;
        TPWrite "running";
    ENDPROC
ENDMODULE
