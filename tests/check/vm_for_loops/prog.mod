MODULE VmForLoops
    ! FOR loops: up, down, STEP given or not, a STEP against the range, a
    ! fractional STEP, bounds evaluated once, nested loops inside a WHILE
    ! whose body reads a free input.  The global i is hidden by the loop
    ! variables named i.
    VAR num i := 100;
    VAR num up := 0;
    VAR num down := 0;
    VAR num auto_down := 0;
    VAR num wrong_way := 0;
    VAR num single := 0;
    VAR num tenths := 0;
    VAR num last_tenth := 0;
    VAR num limit := 2;
    VAR num grown := 0;
    VAR num nested := 0;
    VAR num ones := 0;
    VAR num passes := 0;
    VAR num phase := 0;

    PROC main()
        FOR i FROM 1 TO 4 DO
            up := up + i;
        ENDFOR
        FOR i FROM 5 TO 1 STEP -2 DO
            down := down * 10 + i;
        ENDFOR
        FOR i FROM 3 TO 1 DO
            auto_down := auto_down * 10 + i;
        ENDFOR
        FOR i FROM 1 TO 3 STEP -1 DO
            wrong_way := wrong_way * 10 + i;
        ENDFOR
        FOR i FROM 7 TO 7 DO
            single := single + i;
        ENDFOR
        FOR i FROM 0 TO 1 STEP 0.1 DO
            tenths := tenths + 1;
            last_tenth := i;
        ENDFOR
        FOR i FROM 1 TO limit DO
            limit := limit + 1;
            grown := grown + 1;
        ENDFOR
        phase := 1;
        WHILE passes < 3 DO
            FOR j FROM 1 TO 2 DO
                IF DInput(di_pulse) = 1 ones := ones + 1;
                FOR k FROM j TO 1 STEP -1 DO
                    nested := nested + k;
                ENDFOR
            ENDFOR
            passes := passes + 1;
        ENDWHILE
        phase := 2;
    ENDPROC
ENDMODULE
