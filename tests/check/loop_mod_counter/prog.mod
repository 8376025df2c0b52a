MODULE LoopModCounter
    ! Counts 0, 1, 2, 0, 1, 2, ... forever.
    VAR num x := 0;

    PROC main()
        WHILE TRUE DO
            x := (x + 1) MOD 3;
        ENDWHILE
    ENDPROC
ENDMODULE
