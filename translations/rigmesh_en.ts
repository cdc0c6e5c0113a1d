<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="en">
<context>
    <name>DraggedRigCarry</name>
    <message numerus="yes">
        <source>the rotations of %n joint(s)</source>
        <translation>
            <numerusform>the rotations of %n joint</numerusform>
            <numerusform>the rotations of %n joints</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n pin(s)</source>
        <translation>
            <numerusform>%n pin</numerusform>
            <numerusform>%n pins</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n key(s)</source>
        <translation>
            <numerusform>%n key</numerusform>
            <numerusform>%n keys</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>the rotations of joint(s) %1 (in the merged skeleton they would turn other bones)</source>
        <translation>
            <numerusform>the rotations of joint %1 (in the merged skeleton they would turn other bones)</numerusform>
            <numerusform>the rotations of joints %1 (in the merged skeleton they would turn other bones)</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>the pin(s) of joint(s) %1 (pruned)</source>
        <translation>
            <numerusform>the pin of joint %1 (pruned)</numerusform>
            <numerusform>the pins of joints %1 (pruned)</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>MergePartsCommand</name>
    <message numerus="yes">
        <source>; %n bone(s) pruned</source>
        <translation>
            <numerusform>; %n bone pruned</numerusform>
            <numerusform>; %n bones pruned</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>; %1 lost the pose, pins and keys of %n pruned joint(s)</source>
        <translation>
            <numerusform>; %1 lost the pose, pins and keys of %n pruned joint</numerusform>
            <numerusform>; %1 lost the pose, pins and keys of %n pruned joints</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>MoveKeysCommand</name>
    <message numerus="yes">
        <source>Move %n key(s) of %1 by %2 s</source>
        <translation>
            <numerusform>Move %n key of %1 by %2 s</numerusform>
            <numerusform>Move %n keys of %1 by %2 s</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>PasteKeysCommand</name>
    <message numerus="yes">
        <source>Paste %n key(s) into %1</source>
        <translation>
            <numerusform>Paste %n key into %1</numerusform>
            <numerusform>Paste %n keys into %1</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>RebuildPartCommand</name>
    <message numerus="yes">
        <source>the pose, pins and keys of %n joint(s) were dropped: the new skeleton has no joint there</source>
        <translation>
            <numerusform>the pose, pins and keys of %n joint were dropped: the new skeleton has no joint there</numerusform>
            <numerusform>the pose, pins and keys of %n joints were dropped: the new skeleton has no joint there</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>RigPartCommand</name>
    <message numerus="yes">
        <source>Rig %1 with %n more part(s)</source>
        <translation>
            <numerusform>Rig %1 with %n more part</numerusform>
            <numerusform>Rig %1 with %n more parts</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%1 rigged with %n bone(s)</source>
        <translation>
            <numerusform>%1 rigged with %n bone</numerusform>
            <numerusform>%1 rigged with %n bones</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%1 and %2 more parts rigged as one with %n bone(s)</source>
        <translation>
            <numerusform>%1 and %2 more parts rigged as one with %n bone</numerusform>
            <numerusform>%1 and %2 more parts rigged as one with %n bones</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>; %n vertex(es) saw no bone from inside and follow the closest one</source>
        <translation>
            <numerusform>; %n vertex saw no bone from inside and follows the closest one</numerusform>
            <numerusform>; %n vertices saw no bone from inside and follow the closest one</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>rigmesh::model::SceneItemModel</name>
    <message numerus="yes">
        <source>, bone %1: %n vertices</source>
        <translation>
            <numerusform>, bone %1: %n vertex</numerusform>
            <numerusform>, bone %1: %n vertices</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>rigmesh::model::TimelineEdits</name>
    <message numerus="yes">
        <source>Paste %n key(s)</source>
        <translation>
            <numerusform>Paste %n key</numerusform>
            <numerusform>Paste %n keys</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>rigmesh::widgets::ExchangeController</name>
    <message numerus="yes">
        <source>Imported %n part(s) from %1</source>
        <translation>
            <numerusform>Imported %n part from %1</numerusform>
            <numerusform>Imported %n parts from %1</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>: %n of them without a skeleton, so they cannot be posed yet.</source>
        <translation>
            <numerusform>: %n of them without a skeleton, so it cannot be posed yet.</numerusform>
            <numerusform>: %n of them without a skeleton, so they cannot be posed yet.</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>rigmesh::widgets::KeyDrag</name>
    <message numerus="yes">
        <source>Move keys by %n frame(s)</source>
        <translation>
            <numerusform>Move keys by %n frame</numerusform>
            <numerusform>Move keys by %n frames</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>rigmesh::widgets::PaintTool</name>
    <message numerus="yes">
        <source>Painted %n dab(s), %1 vertices changed</source>
        <translation>
            <numerusform>Painted %n dab, %1 vertices changed</numerusform>
            <numerusform>Painted %n dabs, %1 vertices changed</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>; %n vertex visit(s) skipped: every other bone there is locked</source>
        <translation>
            <numerusform>; %n vertex visit skipped: every other bone there is locked</numerusform>
            <numerusform>; %n vertex visits skipped: every other bone there is locked</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>; %n vertex visit(s) painted on one side only: no mirror partner there</source>
        <translation>
            <numerusform>; %n vertex visit painted on one side only: no mirror partner there</numerusform>
            <numerusform>; %n vertex visits painted on one side only: no mirror partner there</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>rigmesh::widgets::TimelineDock</name>
    <message numerus="yes">
        <source>Keyed %n part(s) at frame %1</source>
        <translation>
            <numerusform>Keyed %n part at frame %1</numerusform>
            <numerusform>Keyed %n parts at frame %1</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Deleted %n key(s)</source>
        <translation>
            <numerusform>Deleted %n key</numerusform>
            <numerusform>Deleted %n keys</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Copied %n key(s)</source>
        <translation>
            <numerusform>Copied %n key</numerusform>
            <numerusform>Copied %n keys</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>rigmesh::widgets::WeightsController</name>
    <message numerus="yes">
        <source>%1: %n vertices changed</source>
        <translation>
            <numerusform>%1: %n vertex changed</numerusform>
            <numerusform>%1: %n vertices changed</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>rigmesh::widgets::WeightsPanel</name>
    <message numerus="yes">
        <source>Vertex %1 of %2: %n bone(s), sum %3</source>
        <translation>
            <numerusform>Vertex %1 of %2: %n bone, sum %3</numerusform>
            <numerusform>Vertex %1 of %2: %n bones, sum %3</numerusform>
        </translation>
    </message>
</context>
</TS>
