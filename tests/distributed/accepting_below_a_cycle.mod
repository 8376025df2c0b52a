MODULE AcceptingBelowACycle
    ! G F done fails only on the loop at line 16 (di_stay = 1 forever). Below it, and also
    ! straight from the start, twelve free inputs set noise: 4,096 states in which done is
    ! still FALSE, each a step from the end. Breadth-first, they come before the loop. In
    ! the product with the automaton of F G !done, each is an accepting state reachable from
    ! the loop's accepting cycle, and OWCTY keeps it; none lies on a cycle itself.
    VAR num count := 0;
    VAR num noise := 0;
    VAR bool done := FALSE;

    PROC main()
        IF DInput(di_mode) = 1 THEN
            WHILE count < 5 DO
                count := count + 1;
            ENDWHILE
            WHILE DInput(di_stay) = 1 DO
            ENDWHILE
            count := 0;
        ENDIF
        noise := DInput(di_b0) + 2 * DInput(di_b1) + 4 * DInput(di_b2) + 8 * DInput(di_b3)
            + 16 * DInput(di_b4) + 32 * DInput(di_b5) + 64 * DInput(di_b6)
            + 128 * DInput(di_b7) + 256 * DInput(di_b8) + 512 * DInput(di_b9)
            + 1024 * DInput(di_b10) + 2048 * DInput(di_b11);
        done := noise >= 0;
    ENDPROC
ENDMODULE
