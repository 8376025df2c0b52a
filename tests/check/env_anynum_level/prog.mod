MODULE EnvLevel
    ! Divides by an analog level that the environment model drives.
    VAR signalai level;
    VAR num share := 0;

    PROC main()
        AliasIO "AI_LEVEL", level;
        WHILE TRUE DO
            share := 6 / level;
        ENDWHILE
    ENDPROC
ENDMODULE
