MODULE CoverageUnreadStatistics
    ! A part counter modulo 3 fed by a free input, and what every cell keeps
    ! besides: a cycle counter and a log line that nothing reads.
    VAR signaldi di_part;
    VAR num parts := 0;
    VAR num nCycles := 0;
    VAR string lastLog := "";

    PROC main()
        AliasIO "DI_PART", di_part;
        WHILE TRUE DO
            IF di_part = 1 THEN
                parts := (parts + 1) MOD 3;
            ENDIF
            IF parts > 5 THEN
                TPWrite "more parts than the counter holds";
            ENDIF
            nCycles := nCycles + 1;
            lastLog := "cycle " + NumToStr(nCycles, 0);
        ENDWHILE
    ENDPROC
ENDMODULE
