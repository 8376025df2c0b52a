MODULE LayerPalletizer
    ! A palletizer that takes its recipe from a PLC through group inputs: box height,
    ! layers per pallet and boxes per layer. Every group input needs a finite domain
    ! when checking, and rapidmc names all of those that lack one in one run.
    PERS tooldata tVacuum := [TRUE,[[0,0,220],[1,0,0,0]],[12,[0,0,110],[1,0,0,0],0,0,0]];
    CONST robtarget pPick := [[800,0,400],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST robtarget pPlace := [[0,900,150],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
    VAR num boxHeight := 0;
    VAR num layersWanted := 0;
    VAR num boxesPerLayer := 0;
    VAR num layer := 0;
    VAR num box := 0;
    VAR num placed := 0;

    PROC main()
        boxHeight := GInput(giBoxHeight);
        layersWanted := GInput(giLayers);
        boxesPerLayer := GInput(giBoxesPerLayer);
        layer := 1;
        WHILE layer <= layersWanted DO
            box := 1;
            WHILE box <= boxesPerLayer DO
                MoveJ Offs(pPick, 0, 0, 100), v1000, z50, tVacuum;
                MoveL pPick, v200, fine, tVacuum;
                SetDO doVacuum, 1;
                MoveL Offs(pPlace, box * 50, 0, layer * boxHeight), v500, fine, tVacuum;
                SetDO doVacuum, 0;
                placed := placed + 1;
                box := box + 1;
            ENDWHILE
            SetGO goLayerDone, layer;
            layer := layer + 1;
        ENDWHILE
    ENDPROC
ENDMODULE
