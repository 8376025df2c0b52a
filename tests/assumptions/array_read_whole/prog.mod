MODULE PlcArrayWhole
    ! Written for the test (issue 28): station flags a PC writes, read by element in one
    ! place and as a whole array, passed on, in another: the whole read takes the values
    ! its elements may take (before, it kept its initial values, so the division by zero
    ! below, with station 2 off, went unseen).
    PERS bool stationOn{3} := [TRUE, TRUE, TRUE];
    VAR num nOn := 0;
    VAR num nShare := 0;

    PROC main()
        IF stationOn{1} nOn := nOn + 1;
        CountOn stationOn;
        nShare := 10 / nOn;
    ENDPROC

    PROC CountOn(bool flags{*})
        nOn := 0;
        FOR i FROM 1 TO Dim(flags, 1) DO
            IF flags{i} nOn := nOn + 1;
        ENDFOR
    ENDPROC
ENDMODULE
