MODULE DomainBetweenLiterals
    ! The only value that opens the gate is 4, which is no literal of the
    ! program: it is the neighbour above 3 and below 5 of the derived domain.
    VAR signalgi gi_code;
    VAR bool open := FALSE;

    PROC main()
        AliasIO "GI_CODE", gi_code;
        WHILE TRUE DO
            IF gi_code > 3 AND gi_code < 5 THEN
                open := TRUE;
            ENDIF
        ENDWHILE
    ENDPROC
ENDMODULE
