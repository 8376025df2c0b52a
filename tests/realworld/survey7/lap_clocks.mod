MODULE lap_clocks
    ! Survey round 7: one stop-watch per round in an array of clocks. The elements of a
    ! clock array start stopped at 0 like a single clock (they were read as no value).
    VAR clock cLap{3};
    VAR num nRound := 0;
    PERS num nLapTime := -1;

    PROC main()
        FOR i FROM 1 TO 2 DO
            nRound := i;
            ClkReset cLap{i};
            ClkStart cLap{i};
            WaitTime 0.5;
            ClkStop cLap{i};
        ENDFOR
        nLapTime := ClkRead(cLap{3});
    ENDPROC
ENDMODULE
