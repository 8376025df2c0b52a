MODULE DeepError
    ! A planted deep error: ERR_DIVZERO once the counter reaches 300, over a thousand steps
    ! down; beside the counter a value mixed from two free inputs takes 97 values, so a
    ! breadth-first search must store about 97 states per step of depth to get there.
    VAR num count := 0;
    VAR num noise := 0;
    VAR num zero := 0;
    VAR num ratio := 0;

    PROC main()
        WHILE TRUE DO
            noise := (noise + DInput(di_a) + 2 * DInput(di_b) + 1) MOD 97;
            count := count + 1;
            IF count = 300 THEN
                ratio := noise / zero;
            ENDIF
        ENDWHILE
    ENDPROC
ENDMODULE
