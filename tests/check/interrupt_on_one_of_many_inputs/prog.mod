MODULE InterruptOnOneOfManyInputs
    ! Written for issue 28: a cell task orders an interrupt on one of its ten inputs and
    ! polls the others. The interrupt's signal must be kept in states (the trap fires when
    ! it changes); the other nine are chosen where they are read, not stored in every state.
    VAR intnum reset_int;
    VAR bool reset_seen := FALSE;
    VAR num parts := 0;

    PROC main()
        CONNECT reset_int WITH on_reset;
        ISignalDI di_reset, 1, reset_int;
        WHILE TRUE DO
            IF di_part1 = 1 AND di_part2 = 1 THEN
                parts := 1;
            ELSEIF di_part3 = 1 OR di_part4 = 1 THEN
                parts := 2;
            ELSEIF di_part5 = 1 AND di_part6 = 0 THEN
                parts := 3;
            ELSEIF di_part7 = 1 OR di_part8 = 1 OR di_part9 = 1 THEN
                parts := 0;
            ENDIF
            WaitTime 0.1;
        ENDWHILE
    ENDPROC

    TRAP on_reset
        reset_seen := TRUE;
        parts := 0;
    ENDTRAP
ENDMODULE
