MODULE Handshake
    ! Another task sets newTarget to TRUE when it has a target; this task polls it in its
    ! endless loop and clears it. The loaded code writes only FALSE, so a party not loaded
    ! must set it: the poll at line 11 reads the stored value or TRUE.
    PERS bool newTarget := FALSE;
    PERS num served := 0;

    PROC main()
        WHILE TRUE DO
            WaitTime 0.25;
            IF newTarget = TRUE THEN
                newTarget := FALSE;
                served := served + 1;
                IF served > 2 served := 0;
            ENDIF
        ENDWHILE
    ENDPROC
ENDMODULE
