MODULE InputReadTwice
    ! The part code is checked, then read again as an index: the PLC may change it between.
    VAR signalgi gi_code;
    VAR bool done{3} := [FALSE, FALSE, FALSE];

    PROC main()
        AliasIO "GI_CODE", gi_code;
        IF gi_code >= 1 AND gi_code <= 3 THEN
            done{gi_code} := TRUE;
        ENDIF
    ENDPROC
ENDMODULE
