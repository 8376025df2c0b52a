MODULE Gantry
    ! Written for the test (issue 28): the gantry loads its eight stations.
    PERS num codes{8} := [0, 0, 0, 0, 0, 0, 0, 0];

    PROC main()
        FOR i FROM 1 TO 8 DO
            codes{i} := 1;
        ENDFOR
    ENDPROC
ENDMODULE
