MODULE Gantry
    ! Written for the test (issue 28): the gantry loads its eight stations and writes the
    ! code it reads from the station (a value its code does not fix).
    PERS num codes{8} := [0, 0, 0, 0, 0, 0, 0, 0];
    VAR num nLoaded := 1;

    PROC main()
        FOR i FROM 1 TO 8 DO
            codes{i} := nLoaded;
        ENDFOR
    ENDPROC
ENDMODULE
