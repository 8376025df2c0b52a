MODULE CoverageDeadRoutine
    ! Reset is never called, and the ELSE branch never runs: mode only
    ! takes the values 1 and 2.
    VAR num mode := 1;

    PROC main()
        WHILE TRUE DO
            IF mode = 1 THEN
                mode := 2;
            ELSEIF mode = 2 THEN
                mode := 1;
            ELSE
                mode := 0;
                Reset;
            ENDIF
        ENDWHILE
    ENDPROC

    PROC Reset()
        mode := 1;
        TPWrite "reset";
    ENDPROC
ENDMODULE
