MODULE RetryRounds
    ! A handler that resets the gripper's power and retries: every round counts the reset
    ! and tries again; the fifth RETRY is one too many (ERR_EXCRTYMAX).  Only the first
    ! round changes was_reset: the later ones assign the value it has.
    VAR num resets := 0;
    VAR bool powered := FALSE;
    VAR bool was_reset := FALSE;
    VAR num parts{8};

    PROC main()
        PowerOn;
        Grip parts{1};
    ENDPROC

    PROC PowerOn()
        SetDO do_power, 1;
        WaitTime 0.2;
        powered := TRUE;
    ENDPROC

    PROC Grip(num part)
        WaitDI di_gripped, 1 \MaxTime:=1;
        parts{resets + 1} := part + 1;
    ERROR
        TPWrite "Grip failed, resetting the power";
        powered := FALSE;
        SetDO do_power, 0;
        PowerOn;
        resets := resets + 1;
        was_reset := TRUE;
        RETRY;
    ENDPROC
ENDMODULE
