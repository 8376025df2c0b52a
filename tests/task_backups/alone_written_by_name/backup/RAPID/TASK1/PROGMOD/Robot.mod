MODULE Robot
    ! Written for the test: the robot waits for startRob, which the receiver task T_RX
    ! sets by its name (SetDataVal) and the robot clears.
    PERS bool startRob := FALSE;
    VAR num zero := 0;
    VAR num x := 0;

    PROC main()
        WHILE TRUE DO
            WaitUntil startRob = TRUE;
            x := 1 / zero;
            startRob := FALSE;
        ENDWHILE
    ENDPROC
ENDMODULE
