MODULE ResetTrap
    ! An interrupt on diReset; diStart and diPart are read by the code only.
    VAR intnum reset_int;
    VAR num slot := 1;
    VAR bool was_reset := FALSE;
    VAR num bins{3} := [0, 0, 0];

    PROC main()
        CONNECT reset_int WITH OnReset;
        ISignalDI diReset, 1, reset_int;
        WHILE TRUE DO
            WaitDI diStart, 1;
            IF DInput(diPart) = 1 THEN
                slot := slot + 1;
                bins{slot} := 1;
            ENDIF
        ENDWHILE
    ENDPROC

    TRAP OnReset
        was_reset := TRUE;
        slot := 1;
        bins := [0, 0, 0];
    ENDTRAP
ENDMODULE
