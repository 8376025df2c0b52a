MODULE VmNumFloat32
    ! num is IEEE single precision: every result is rounded to float32.
    VAR num tenth := 0;
    VAR num steps := 0;
    VAR num big := 16777216;
    VAR num third := 0;
    VAR num back := 0;
    VAR num q1 := 0;
    VAR num q2 := 0;
    VAR num q3 := 0;
    VAR num m1 := 0;
    VAR num m2 := 0;
    VAR num m3 := 0;
    VAR num zero := 0;
    VAR num flip := 0;
    VAR num phase := 0;

    PROC main()
        WHILE steps < 10 DO
            tenth := tenth + 0.1;
            steps := steps + 1;
        ENDWHILE
        big := big + 1;
        big := big + 2;
        third := 1 / 3;
        back := third * 3;
        q1 := -7 DIV 2;
        q2 := 7 DIV -2;
        q3 := -7 DIV -2;
        m1 := -7 MOD 2;
        m2 := 7 MOD -2;
        m3 := -7 MOD -2;
        flip := -zero;
        phase := 1;
        WHILE TRUE DO
            ! -0 and 0 alternate here; they are the same value (one state).
            flip := -flip;
        ENDWHILE
    ENDPROC
ENDMODULE
