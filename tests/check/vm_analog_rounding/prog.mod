MODULE VmAnalogRounding
    ! AInput returns a num: a single-precision value, whatever the input
    ! domain says.  0.1 read from AI_LEVEL is float32(0.1), the num the
    ! literal 0.1 is.
    VAR signalai level;
    VAR num reading := 0;
    VAR num copy := 0.1;

    PROC main()
        AliasIO "AI_LEVEL", level;
        WHILE TRUE DO
            reading := AInput(level);
            copy := reading;
        ENDWHILE
    ENDPROC
ENDMODULE
