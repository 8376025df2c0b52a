MODULE Robot
    ! Written for the test (issue 28): phase is written here and by the receiver task T_RX.
    ! The robot waits for the receiver's phase 2 and for its own gripper flag, which only
    ! the code after the wait sets: the wait never ends, whatever T_RX writes.
    PERS num phase := 0;
    VAR bool gripped := FALSE;

    PROC main()
        phase := 1;
        WaitUntil phase = 2 AND gripped;
        gripped := TRUE;
        phase := 0;
    ENDPROC
ENDMODULE
