MODULE RuntimeAnalogZero
    ! An analog input takes the values --input-domain gives it.
    VAR signalai level;
    VAR num share := 0;

    PROC main()
        AliasIO "AI_LEVEL", level;
        WHILE TRUE DO
            share := 100 / level;
        ENDWHILE
    ENDPROC
ENDMODULE
