MODULE LoopToggle
    ! A loop that never ends, setting and clearing a flag.
    VAR bool flag := FALSE;

    PROC main()
        WHILE TRUE DO
            flag := TRUE;
            flag := FALSE;
        ENDWHILE
    ENDPROC
ENDMODULE
