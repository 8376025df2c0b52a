MODULE DomainAnalogCompared
    ! A tank level read from an analog input, only compared with 2.5 and 4:
    ! the derived domain is {1.5, 2.5, 3.25, 4, 5} (each number, the middle
    ! between them, one beyond each end).
    VAR signalai ai_level;
    VAR num state := 0;

    PROC main()
        AliasIO "AI_LEVEL", ai_level;
        WHILE TRUE DO
            IF AInput(ai_level) > 2.5 AND ai_level < 4 THEN
                state := 1;
            ELSEIF ai_level = 4 THEN
                state := 2;
            ELSEIF ai_level <= 2.5 THEN
                state := 3;
            ELSE
                state := 4;
            ENDIF
        ENDWHILE
    ENDPROC
ENDMODULE
