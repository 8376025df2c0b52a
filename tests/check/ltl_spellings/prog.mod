MODULE LtlSpellings
    ! flag flips and count steps through 0..3 in every pass, for ever.
    VAR bool flag := FALSE;
    VAR num count := 0;

    PROC main()
        WHILE TRUE DO
            flag := NOT flag;
            count := (count + 1) MOD 4;
        ENDWHILE
    ENDPROC
ENDMODULE
