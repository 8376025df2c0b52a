MODULE ArrayLoop
    ! A path of twelve robtargets computed element by element, then an index one too far.
    VAR robtarget waypoints{12};
    VAR num count := 12;
    VAR num spare{40};
    VAR string label := "path";

    PROC main()
        FOR i FROM 1 TO count DO
            waypoints{i} := [[932.4 + i, 1557.5, 2189.5], [1, 0, 0, 0], [0, 0, 0, 0],
                             [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];
        ENDFOR
        waypoints{count + 1} := waypoints{count};
    ENDPROC
ENDMODULE
